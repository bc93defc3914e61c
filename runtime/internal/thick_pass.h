#pragma once
// Single scattering of the optically thick objects (SampleScheme::OpticallyThick):
// no samples, each pixel's view ray integrated from the nearest front face
// (optically_thick.frag), with the light's path through the medium read from
// a distance map of the object's own mesh per light (blocker_shadows.h, drawn
// in prepare when the lights or the placement change).
#include "runtime/internal/gl_program.h"
#include "runtime/internal/render_pass.h"

namespace lucent {

class ThickPass final : public RenderPass {
public:
    void prepare(FrameContext& frame) override;
    void draw(FrameContext& frame) override;

private:
    // Linked on first use: only scenes with optically thick objects need it.
    GlProgramVariants program_{{{GL_VERTEX_SHADER, "mesh.vert"}, {GL_FRAGMENT_SHADER, "optically_thick.frag"}}};
};

}  // namespace lucent
