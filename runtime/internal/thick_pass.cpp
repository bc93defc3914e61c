#include "runtime/internal/thick_pass.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>

#include "runtime/internal/frame_targets.h"
#include "runtime/internal/gpu_layout.h"
#include "runtime/internal/placement_uniforms.h"

namespace lucent {

namespace {
// The lights optically_thick.frag loops over: the lights, then the environment's directions.
std::vector<Light> allLights(const GpuLights& lights) {
    std::vector<Light> all = lights.lights;
    all.insert(all.end(), lights.environment.begin(), lights.environment.end());
    return all;
}
}  // namespace

void ThickPass::prepare(FrameContext& frame) {
    if (!frame.options.scattering) return;
    for (GpuObject& o : frame.objects) {
        if (!o.opticallyThick) {
            o.entryDistances.reset();
            continue;
        }
        if (!o.entryDistances) {
            o.entryDistances = std::make_unique<EntryDistances>(o.bounds);
            o.entryDistancesValid = false;
        }
        if (o.entryDistancesValid) continue;
        o.entryDistances->render(*o.mesh, allLights(frame.lights), o.placement);
        o.entryDistancesValid = true;
    }
}

void ThickPass::draw(FrameContext& frame) {
    const bool anyThick =
        std::any_of(frame.objects.begin(), frame.objects.end(), [](const GpuObject& o) { return o.opticallyThick; });
    if (!frame.options.scattering || !anyThick) return;
    const GlProgram& p = program_.get();
    glUseProgram(p.id());
    glUniformMatrix4fv(p.uniform("viewProjection"), 1, GL_FALSE, glm::value_ptr(frame.viewProjection));
    glUniform1i(p.uniform("lightCount"), frame.lights.withEnvironment());
    glUniform3fv(p.uniform("cameraPosition"), 1, glm::value_ptr(frame.view.cameraPosition));
    glBindTextureUnit(0, frame.targets.frontDepth());
    glUniform1i(p.uniform("frontDepth"), 0);
    glBindTextureUnit(gpu::kUnitInsideSegments, frame.targets.insideSegments());
    glUniform1i(p.uniform("insideSegments"), GLint(gpu::kUnitInsideSegments));
    glUniform1i(p.uniform("entryPlanes"), GLint(gpu::kUnitEntryPlanes));
    glUniform1i(p.uniform("entryExits"), GLint(gpu::kUnitEntryExits));
    glUniform1i(p.uniform("nextEntries"), GLint(gpu::kUnitNextEntries));
    // Only the nearest front face is shaded, and llvmpipe runs a fragment to its
    // discard: culling the back faces halves the pass. A camera inside an object
    // sees its back faces, and the ray from them has no medium left before it.
    if (frame.targets.cameraInside()) {
        glDisable(GL_CULL_FACE);
    } else {
        glEnable(GL_CULL_FACE);
        glCullFace(GL_BACK);
    }
    glDepthMask(GL_FALSE);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE);
    for (const GpuObject& o : frame.objects) {
        if (!o.opticallyThick || !o.entryDistances) continue;
        o.entryDistances->bind();
        glUniform3fv(p.uniform("albedo"), 1, glm::value_ptr(glm::vec3(o.albedo)));
        glUniform3fv(p.uniform("extinction"), 1,
                     glm::value_ptr(glm::vec3(o.extinction) * frame.options.extinctionScale));
        glUniform1f(p.uniform("g"), float(o.g));
        setMeshPlacement(p, o.placement);
        o.mesh->draw();
    }
}

}  // namespace lucent
