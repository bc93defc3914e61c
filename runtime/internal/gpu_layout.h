// The layouts the GPU sees, declared once for C++ and GLSL (Filament's way):
// C++ includes this header; every shader that needs it says
// `#include "gpu_layout.h"`, which the runtime resolves from the embedded copy
// (runtime/internal/shader_source.h). Only what both languages parse goes here:
// structs of vec4/mat4 (std430 lays them out as C++ does) and integer constants.
#ifndef LUCENT_GPU_LAYOUT_H
#define LUCENT_GPU_LAYOUT_H

#ifdef __cplusplus
#include <glm/glm.hpp>
namespace lucent::gpu {
using glm::mat4;
using glm::vec4;
#define LUCENT_GPU_CONSTANT(name, value) inline constexpr int name = value;
#else
#define LUCENT_GPU_CONSTANT(name, value) const int name = value;
#endif

// Shader storage buffer bindings, and the lights' uniform block (lights.glsl).
LUCENT_GPU_CONSTANT(kBindingSamples, 0)        // Sample[]: one object's samples
LUCENT_GPU_CONSTANT(kBindingLights, 1)         // uniform block Light[kMaxLights]: the scene's lights
LUCENT_GPU_CONSTANT(kBindingReceived, 2)       // Received[]: the cached light each sample receives
LUCENT_GPU_CONSTANT(kBindingShadowViews, 3)    // mat4[]: view-projection of each blocker shadow layer
LUCENT_GPU_CONSTANT(kBindingTracedDepths, 4)   // vec4[sample][light]: traced optical depths (traced_light.h)
LUCENT_GPU_CONSTANT(kBindingEnvironmentSh, 5)  // vec4[sample][bands^2 + 1]: the environment's SH (environment_sh.comp)

// Texture units of the sample programs.
LUCENT_GPU_CONSTANT(kUnitRaySegments, 0)      // per pixel [t0, t1] inside the objects
LUCENT_GPU_CONSTANT(kUnitShadowDistances, 1)  // blocker distance maps (runtime/internal/blocker_shadows.h)
LUCENT_GPU_CONSTANT(kUnitGridSource, 2)       // a multiple-scattering grid's source (runtime/internal/grid_pass.h)
LUCENT_GPU_CONSTANT(kUnitGridExtinction, 3)   // and its extinction
LUCENT_GPU_CONSTANT(kUnitInsideSegments, 4)   // per pixel, the two intervals inside the objects
LUCENT_GPU_CONSTANT(kUnitGridRefraction, 5)   // a multiple-scattering grid's index and its gradient
LUCENT_GPU_CONSTANT(kUnitCoefficients, 6)     // float texture buffer: SH coefficients [sample][channel][coefficient]
LUCENT_GPU_CONSTANT(kUnitRefractedRays, 7)    // per pixel, its stretches inside a refracting object
LUCENT_GPU_CONSTANT(kUnitEntryPlanes, 8)      // an optically thick object's nearest entries (entry_distances.h),
LUCENT_GPU_CONSTANT(kUnitEntryExits, 9)       // the exits after them
LUCENT_GPU_CONSTANT(kUnitNextEntries, 10)     // and the entries after those

// The intervals inside the objects a pixel's ray keeps apart (runtime/internal/segment.frag).
LUCENT_GPU_CONSTANT(kMaxRaySegments, 2)
// The stretches of a pixel's ray inside a refracting object: the refracted one
// and those Fresnel reflects inside after it (runtime/internal/refracted_view.h).
LUCENT_GPU_CONSTANT(kRefractedStretches, 2)
// Point-sprite proxies (scatter.geom, POINT_PROXIES) cover a box in up to this
// many points along each screen axis.
LUCENT_GPU_CONSTANT(kPointProxyTiles, 4)
// At most this many SH bands hold each sample's environment light times its
// attenuation (environment_sh.comp); per sample, one record per coefficient
// (rgb), then one for the direction the light falls off fastest in (xyz).
LUCENT_GPU_CONSTANT(kEnvironmentShMaxBands, 8)
// The lights' uniform block holds this many: core/limits.h's kMaxLights (12 KiB).
LUCENT_GPU_CONSTANT(kMaxLights, 256)

struct Light {
    vec4 position;  // w = 1: point light at xyz; w = 0: directional, xyz = direction of travel
    vec4 power;     // rgb: intensity (W/sr) or irradiance (W/m^2); w: a sphere light's radius (0: a point)
    vec4 spot;      // a spot's cone as core/scene.h's spotCoefficients; (0, 0, 0, 1) for any other light
};

struct Sample {
    vec4 centreWidth;  // world-space centre, Gaussian standard deviation
    vec4 scattering;   // sigma_t times the partition-of-unity weight, per channel: times the albedo, sigma_s
    vec4 extinction;   // sigma_t at the centre, per channel
    vec4 region;       // [lo, hi] of its density slab along regionAxis; the ball's curvature, share
    vec4 image;        // the centre mirrored across the nearest boundary of its region
    vec4 ball;         // its boundary ball (core/sample_set.h): outward normal, depth (< 0: none)
};

// What a sample receives from the lights (runtime/internal/sample_light.glsl).
struct Received {
    vec4 light;         // sum_j p E_j psi_i(w_j)
    vec4 towardLights;  // sum_j share_j w_j
    vec4 falloff;       // sum_j share_j 2 w_j / r_j (point lights)
};

#ifdef __cplusplus
static_assert(sizeof(Light) == 3 * sizeof(vec4));
static_assert(sizeof(Sample) == 6 * sizeof(vec4));
static_assert(sizeof(Received) == 3 * sizeof(vec4));
}  // namespace lucent::gpu
#endif
#undef LUCENT_GPU_CONSTANT

#endif
