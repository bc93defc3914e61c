#pragma once
// Hard shadows of a translucent object's opaque blockers (the Lucent scheme).
// A blocker's shadow is a step in exp(-tau(b_i, w)) that low-order SH smear over
// the whole sphere (the torus cube's error at order 5). So the preprocessor
// projects psi_i with the blockers filled by the medium, which is smooth, and the
// runtime multiplies each light by its visibility past the blockers, read here:
// per light, the distance along its rays to the nearest blocker surface, in six
// 90-degree cube faces around a point light or one orthographic view along a
// directional light (layers 6j..6j+5 of one R32F texture array; the view-
// projection of each layer in a storage buffer). sample_light.glsl reads
// them at each sample's centre.
#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "core/scene.h"
#include "core/similarity.h"
#include "core/triangle_mesh.h"
#include "runtime/internal/gl_program.h"
#include "runtime/internal/gpu_mesh.h"

namespace lucent {

class BlockerShadows {
public:
    explicit BlockerShadows(const std::vector<const TriangleMesh*>& blockers);
    ~BlockerShadows();
    BlockerShadows(const BlockerShadows&) = delete;
    BlockerShadows& operator=(const BlockerShadows&) = delete;

    // Renders the maps for these lights (when they or the placement change), the
    // blockers placed in the world as their object stands. Leaves the draw
    // framebuffer, viewport and blending for the caller to set again.
    void render(const std::vector<Light>& lights, const Similarity& placement);
    // The distance texture on this unit, the layer matrices on kBindingShadowViews.
    void bind(GLuint textureUnit) const;

private:
    std::vector<std::unique_ptr<GpuMesh>> meshes_;
    Bounds3 bounds_;  // of the blockers, in object space
    GlProgram program_;
    GLuint texture_ = 0, framebuffer_ = 0, views_ = 0;
    int layers_ = 0, size_ = 0;
    void release();
};

}  // namespace lucent
