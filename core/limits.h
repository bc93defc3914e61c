#pragma once
// The ranges Lucent computes right, enforced where scenes and meshes are read
// (docs/robustness.md lists them with the reasons). Outside them an input is
// refused with the limit named, never rendered to a silent black or wrong image.
#include <cstddef>

namespace lucent {

// |coordinate| of cameras, lights, grid bounds and mesh vertices, in scene units:
// Embree and the OpenGL passes work in single precision (max 3.4e38), and
// squared distances must stay representable.
inline constexpr double kMaxCoordinate = 1e13;
// An object's bounding-box diagonal, in scene units: below this, single-precision
// ray casting and rasterisation lose the object.
inline constexpr double kMinObjectSize = 1e-9;
// An object's uniform scale (the scene's "transform"): the placed object must
// still lie within kMaxCoordinate and above kMinObjectSize, checked on loading.
inline constexpr double kMinScale = 1e-9;
inline constexpr double kMaxScale = 1e9;
// Light intensity (W/sr), irradiance (W/m^2), sigma_t and densities: the images
// and sample files store single-precision floats.
inline constexpr double kMaxMagnitude = 1e30;
// Lights per scene: the blocker shadow maps take six layers per light, and
// OpenGL guarantees 2048 layers per texture array.
inline constexpr size_t kMaxLights = 256;
// Directional lights an environment light may become in ss, lbl and mdom
// (--env-lights): a scene with an environment keeps room for them among kMaxLights.
inline constexpr size_t kMaxEnvironmentLights = 128;

}  // namespace lucent
