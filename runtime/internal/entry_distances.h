#pragma once
// Where each light's light enters an optically thick object and how far it goes
// through the medium (ThickPass, optically_thick.frag). Per light, in the layers
// of blocker_shadow_views.h (six cube faces around a point light, one
// orthographic view along a directional light), along its rays: the plane of
// the nearest entry into the object's closed mesh (RGBA32F: outward normal,
// and its dot product with the plane's points), the distance to the nearest
// exit (R32F) and to the next entry beyond it (R32F). Light through a part,
// across air and into the next part (thin ribs, a plate's holes) crosses only
// the medium; a third part on the way is taken as medium all along.
#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "core/scene.h"
#include "core/similarity.h"
#include "core/math.h"
#include "runtime/internal/gl_program.h"
#include "runtime/internal/gpu_mesh.h"

namespace lucent {

class EntryDistances {
public:
    // For a mesh of these bounds (object space); render draws it.
    explicit EntryDistances(const Bounds3& bounds);
    ~EntryDistances();
    EntryDistances(const EntryDistances&) = delete;
    EntryDistances& operator=(const EntryDistances&) = delete;

    // Renders the maps for these lights, the mesh placed in the world. Leaves the
    // draw framebuffer, viewport and blending for the caller to set again.
    void render(const GpuMesh& mesh, const std::vector<Light>& lights, const Similarity& placement);
    // The entry planes on kUnitEntryPlanes, the exits on kUnitEntryExits, the next
    // entries on kUnitNextEntries, the layer matrices on kBindingShadowViews.
    void bind() const;

private:
    Bounds3 bounds_;  // of the mesh, in object space
    GlProgram program_;
    GLuint planes_ = 0, exits_ = 0, next_ = 0, depth_ = 0, framebuffer_ = 0, views_ = 0;
    int layers_ = 0, size_ = 0;
    void allocate(int layers, int size);
    void drawLayers(const GpuMesh& mesh, const std::vector<Light>& lights, const std::vector<glm::mat4>& views,
                    int pass);
    void release();
};

}  // namespace lucent
