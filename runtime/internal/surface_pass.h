#pragma once
// Light from the objects' nearest front faces, tested against the host's depth,
// writing none: the reflected surface term (thesis 3.4.1, surface.frag) and the
// closed-form single scattering of optically thick objects (optically_thick.frag).
#include "runtime/internal/gl_program.h"
#include "runtime/internal/render_pass.h"

namespace lucent {

class SurfacePass final : public RenderPass {
public:
    void draw(FrameContext& frame) override;

private:
    void begin(const GlProgram& program, const FrameContext& frame) const;
    GlProgram surfaceProgram_{{GL_VERTEX_SHADER, "mesh.vert"}, {GL_FRAGMENT_SHADER, "surface.frag"}};
    // Linked on first use: only scenes with optically thick objects need it.
    GlProgramVariants thickProgram_{{{GL_VERTEX_SHADER, "mesh.vert"}, {GL_FRAGMENT_SHADER, "optically_thick.frag"}}};
};

}  // namespace lucent
