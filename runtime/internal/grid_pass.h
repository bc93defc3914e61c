#pragma once
// The view pass of the hybrid (thesis 4.6.2): each pixel's ray segment inside
// the translucent objects marched through each object's multiple-scattering grid
// (core/scattering_grid.h, made by hybrid/), added to the frame (grid_march.frag).
// The grids arrive as plain voxels: the runtime never sees OpenCL.
#include <vector>

#include "core/scattering_grid.h"
#include "runtime/internal/gl_program.h"
#include "runtime/internal/render_pass.h"

namespace lucent {

class GridPass final : public RenderPass {
public:
    GridPass() = default;
    ~GridPass() override;
    GridPass(const GridPass&) = delete;
    GridPass& operator=(const GridPass&) = delete;

    void add(const ScatteringGrid& grid);  // uploaded at once; the grid need not outlive the pass
    void clear();
    bool empty() const { return grids_.empty(); }
    void draw(FrameContext& frame) override;

private:
    struct GpuGrid {
        GLuint source = 0, extinction = 0;  // 3D RGB32F textures, trilinear
        GLuint refraction = 0;              // RGBA32F (n, grad n), or 0: index-matched
        Bounds3 bounds;
        float voxel = 0;
        float ior = 1;  // the medium's own, where refraction is not 0
    };
    std::vector<GpuGrid> grids_;
    // Linked on first use: only scenes with grids (the hybrid methods) draw this pass.
    GlProgramVariants program_{{{GL_VERTEX_SHADER, "fullscreen.vert"}, {GL_FRAGMENT_SHADER, "grid_march.frag"}}};
};

}  // namespace lucent
