#pragma once
// Light reflected at the objects' nearest front faces, tested against the host's
// depth, writing none: the surface term (thesis 3.4.1), deferred.
#include "runtime/internal/gl_program.h"
#include "runtime/internal/render_pass.h"

namespace lucent {

class SurfacePass final : public RenderPass {
public:
    SurfacePass();
    ~SurfacePass() override;
    SurfacePass(const SurfacePass&) = delete;
    SurfacePass& operator=(const SurfacePass&) = delete;
    void draw(FrameContext& frame) override;

    // Objects with a surface whose normals one batch keeps (surface.frag's kSurfaceBatch).
    static constexpr int kBatch = 32;

private:
    void drawSurfaces(FrameContext& frame);
    // Each pixel's nearest face of the batch's objects (surface_normals.frag), then its light (surface.frag).
    void keepNearestFaces(const FrameContext& frame, size_t first, size_t end);
    void lightKeptFaces(const FrameContext& frame, size_t first, size_t end) const;
    void resize(int width, int height);
    void release();

    GlProgram normalsProgram_{{GL_VERTEX_SHADER, "mesh.vert"}, {GL_FRAGMENT_SHADER, "surface_normals.frag"}};
    GlProgram surfaceProgram_{{GL_VERTEX_SHADER, "fullscreen.vert"}, {GL_FRAGMENT_SHADER, "surface.frag"}};
    // The kept faces: RGBA32F normal and slot, DEPTH_COMPONENT32F depth.
    GLuint framebuffer_ = 0, normals_ = 0, depths_ = 0;
    int width_ = 0, height_ = 0;
};

}  // namespace lucent
