#include "runtime/internal/surface_pass.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>

#include "runtime/internal/frame_targets.h"
#include "runtime/internal/placement_uniforms.h"

namespace lucent {

void SurfacePass::begin(const GlProgram& p, const FrameContext& frame) const {
    glUseProgram(p.id());
    glUniformMatrix4fv(p.uniform("viewProjection"), 1, GL_FALSE, glm::value_ptr(frame.viewProjection));
    glUniform1i(p.uniform("lightCount"), frame.lights.withEnvironment());
    glUniform3fv(p.uniform("cameraPosition"), 1, glm::value_ptr(frame.view.cameraPosition));
    glBindTextureUnit(0, frame.targets.frontDepth());
    glUniform1i(p.uniform("frontDepth"), 0);
    // Only the nearest front face is shaded, and llvmpipe runs a fragment to its
    // discard: culling the back faces halves the pass (a camera inside an object
    // sees them, so they stay there).
    if (frame.targets.cameraInside()) {
        glDisable(GL_CULL_FACE);
    } else {
        glEnable(GL_CULL_FACE);
        glCullFace(GL_BACK);
    }
    glDepthMask(GL_FALSE);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE);
}

void SurfacePass::draw(FrameContext& frame) {
    if (frame.options.surface) {
        const GlProgram& p = surfaceProgram_;
        begin(p, frame);
        for (const GpuObject& o : frame.objects) {
            if (!o.surface) continue;
            glUniform3fv(p.uniform("diffuse"), 1, glm::value_ptr(glm::vec3(o.surface->diffuse)));
            glUniform3fv(p.uniform("specular"), 1, glm::value_ptr(glm::vec3(o.surface->specular)));
            glUniform1f(p.uniform("shininess"), float(o.surface->shininess));
            setMeshPlacement(p, o.placement);
            o.mesh->draw();
        }
    }
    const bool anyThick =
        std::any_of(frame.objects.begin(), frame.objects.end(), [](const GpuObject& o) { return o.opticallyThick; });
    if (frame.options.scattering && anyThick) {
        const GlProgram& p = thickProgram_.get();
        begin(p, frame);
        for (const GpuObject& o : frame.objects) {
            if (!o.opticallyThick) continue;
            glUniform3fv(p.uniform("albedo"), 1, glm::value_ptr(glm::vec3(o.albedo)));
            glUniform1f(p.uniform("g"), float(o.g));
            setMeshPlacement(p, o.placement);
            o.mesh->draw();
        }
    }
}

}  // namespace lucent
