#pragma once
// The frame as a small composer over passes (runtime/scattering_renderer.cpp):
// the frame targets first (frame_targets.h), then each pass in order, every one
// adding light to the host's framebuffer. A new kind of light (a multiple-
// scattering grid, say) is one more RenderPass; nothing else changes.
#include <memory>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "core/mesh_raycaster.h"
#include "core/scene.h"
#include "runtime/internal/gl.h"
#include "runtime/internal/blocker_shadows.h"
#include "runtime/internal/entry_distances.h"
#include "runtime/internal/gpu_mesh.h"
#include "runtime/internal/gpu_samples.h"
#include "runtime/internal/refracted_view.h"
#include "runtime/scattering_renderer.h"
#include "runtime/view_setup.h"

namespace lucent {

class FrameTargets;

// One translucent object as the passes hold it on the GPU.
struct GpuObject {
    std::unique_ptr<GpuMesh> mesh;
    std::unique_ptr<GpuSamples> samples;
    const SampleSet* sampleSet = nullptr;  // the caller's, which samples holds on the GPU
    const VolumeObject* volume = nullptr;  // TranslucentObject::volume
    Similarity placement;                  // object to world; mesh, blockers and samples stay in object space
    double g = 0.0;
    std::optional<SurfaceDesc> surface;
    std::vector<std::unique_ptr<GpuMesh>> blockers;
    const TriangleMesh* boundaryMesh = nullptr;  // the caller's (TranslucentObject::mesh), object space
    Bounds3 bounds;                              // of boundaryMesh
    // Is the camera inside? Built the first time the camera stands inside the
    // bounds: a ray caster (a BVH over every face) is wasted on the usual camera
    // outside (containsPoint, frame_targets.cpp).
    std::unique_ptr<MeshRaycaster> boundary;
    std::unique_ptr<BlockerShadows> shadows;  // the Lucent scheme's blockers, shadowed per light
    bool shadowsValid = false;
    Rgb albedo{0.0};
    bool opticallyThick = false;  // drawn by ThickPass (thick_pass.h), no samples
    Rgb extinction{0.0};          // sigma_t of the medium, where the density is least (ThickPass)
    // ThickPass's distances from each light to where its light enters the mesh.
    std::unique_ptr<EntryDistances> entryDistances;
    bool entryDistancesValid = false;
    RefractedView refractedView;  // the view through its boundary, when it refracts (SamplePass::refracted)
};

// The scene's lights in the kBindingLights buffer: first the lights
// (ScatteringRenderer::setLights), which every pass loops over, then the
// environment's directional lights (setEnvironment), which the surfaces and the
// closed forms loop over and the samples read projected onto SH (environment_sh.comp).
struct GpuLights {
    GLuint buffer = 0;
    std::vector<Light> lights;
    std::vector<Light> environment;  // ScatteringRenderer::setEnvironment's, after lights in the block
    int count() const { return int(lights.size()); }
    int environmentCount() const { return int(environment.size()); }
    int withEnvironment() const { return count() + environmentCount(); }
};

// What every pass of one frame sees.
struct FrameContext {
    const ViewSetup& view;
    const DrawOptions& options;
    std::vector<GpuObject>& objects;
    const GpuLights& lights;
    const FrameTargets& targets;
    glm::mat4 viewProjection;
    GLuint hostFramebuffer = 0;  // where the passes add their light
    // The scattering pass runs at 1/scatterScale of the resolution, through
    // scatterView and scatterTargets (the full ones when scatterScale is 1),
    // and is upsampled into the host's framebuffer (runtime/internal/upsample.frag).
    int scatterScale = 1;
    const ViewSetup* scatterView = nullptr;
    const FrameTargets* scatterTargets = nullptr;
};

class RenderPass {
public:
    virtual ~RenderPass() = default;
    // Offscreen work before the frame targets are drawn (shadow maps, caches).
    // May leave any framebuffer, viewport and blending bound.
    virtual void prepare(FrameContext&) {}
    // Adds this pass's light to the host's framebuffer (bound, viewport set).
    virtual void draw(FrameContext& frame) = 0;
};

}  // namespace lucent
