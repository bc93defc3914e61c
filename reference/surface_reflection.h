#pragma once
// The reflected surface term both ground truths add at the first front face a
// camera ray meets: an energy-normalised Phong BRDF times each light's
// irradiance, direct light only (DESIGN of the surface pass, thesis 3.4.1).
#include <vector>

#include "core/math.h"
#include "core/scene.h"
#include "core/volume_object.h"

namespace lucent {

// Radiance towards the camera at x with unit normal n, for a ray travelling along viewDir.
Rgb phongSurfaceReflection(const SurfaceDesc& surface, const std::vector<Light>& lights, const Vec3& x, const Vec3& n,
                           const Vec3& viewDir);

// The surface term of the first front face of an object with a surface that
// the ray from origin along dir meets before tStop; black where it meets none.
Rgb firstSurfaceReflection(const std::vector<VolumeObject>& objects, const std::vector<Light>& lights,
                           const Vec3& origin, const Vec3& dir, double tStop);

}  // namespace lucent
