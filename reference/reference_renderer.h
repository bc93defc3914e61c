#pragma once
// The ground truth for single scattering (DESIGN.md "Units and conventions"):
// for every pixel, the integral along the camera ray through each object of
//   T(cam, x) sigma_s(x) p(w_view, w_light) sum_j E_j(x) T(x, l_j)
// computed on the exact mesh and density, with no samples and no spherical
// harmonics, by adaptive Simpson quadrature to a relative tolerance.
//
// At a refracting boundary (an object whose ior is not 1) the camera ray
// splits into its Fresnel-reflected and refracted parts, each weighted by its
// share and followed in turn (total internal reflection included), with the
// 1/n^2 of radiance crossing in and n^2 crossing out; the light reaches each
// point through the boundary as the path tracer's next-event estimation finds
// it (core/refraction.h). It is then what `--method path --max-scatter 1`
// converges to, without its noise.
//
// An environment light is integrated over kReferenceEnvironmentDirections
// directions drawn from its map (EnvironmentMap::stratifiedSamples) and as many
// drawn from the phase function about the view, weighed by the balance
// heuristic: a quasi-Monte Carlo quadrature of the sphere that finds both the
// map's bright parts and a peaked phase function's lobe. Through a refracting
// boundary, and in the surface term, the map's directions alone serve, as
// directional lights (EnvironmentMap::asDirectionalLights).
#include <vector>

#include "core/environment_map.h"
#include "core/method.h"
#include "core/image.h"
#include "core/scene.h"
#include "core/volume_object.h"

namespace lucent {

// The largest sigma_t times object size (the size including its distance from
// the origin) the reference resolves: Embree's single-precision boundaries are
// uncertain by about 1e-7 of it. Measured on the unit sphere (size 3.46, its
// diagonal) against the closed form of an optically thick medium: at sigma_t 1e6
// 0.03% off, at 3e6 0.5%, at 1e7 3.7%.
inline constexpr double kMaxResolvedOpticalSize = 4e6;

// Directions the reference integrates an environment over (as directional
// lights drawn from its map), and the path tracer's surface term reflects.
inline constexpr int kReferenceEnvironmentDirections = 256;

struct ReferenceSettings {
    double tolerance = 1e-3;  // relative error target of each pixel's integral
    bool surface = true;      // add the Phong surface reflection of objects that have a surface
    int threads = 0;          // 0: all cores
    RowShare rows;            // the rows to render; the others stay 0
};

class ReferenceRenderer {
public:
    ReferenceRenderer(const SceneDesc& scene, const std::vector<VolumeObject>& objects,
                      const EnvironmentMap* environment = nullptr);
    Image render(const ReferenceSettings& settings) const;
    // Radiance along one ray (exposed for tests).
    Rgb radiance(const Vec3& origin, const Vec3& dir, const ReferenceSettings& settings) const;

private:
    // radiance() less the surface term in a scene with a refracting boundary
    // (reference_refracted.cpp): the ray followed from boundary to boundary.
    Rgb refractedRadiance(const Vec3& origin, const Vec3& dir, const ReferenceSettings& settings) const;
    // sum_j p E_j(x) T(x, l_j), the lights reaching x along straight lines.
    Rgb straightLights(const VolumeObject& object, const Vec3& x, const Vec3& viewDir) const;
    // The environment's share of straightLights (the quadrature above).
    Rgb straightEnvironment(const VolumeObject& object, const Vec3& x, const Vec3& viewDir) const;
    Rgb inScattered(const VolumeObject& object, const Vec3& x, const Vec3& viewDir) const;
    double densityPathAllObjects(const Vec3& origin, const Vec3& dir, double tMax) const;

    const SceneDesc& scene_;
    const std::vector<VolumeObject>& objects_;
    const EnvironmentMap* environment_;
    std::vector<Light> lights_;                               // the scene's and the environment's
    std::vector<EnvironmentMap::Sample> environmentSamples_;  // the map's directions
    bool refracting_ = false;                                 // some object's ior differs from 1
};

}  // namespace lucent
