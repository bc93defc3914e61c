#pragma once
// Light reaching a point of the media, as both ground truths gather it: the
// direction to the light, its irradiance there (1/d^2 for point lights), and
// the transmittance along the way through every object (zero through a blocker).
#include <functional>
#include <optional>
#include <vector>

#include "core/math.h"
#include "core/refraction.h"
#include "core/scene.h"
#include "core/volume_object.h"

namespace lucent {

struct LightArrival {
    Vec3 toLight;     // unit, from x towards the light
    double distance;  // to a point light; infinity for a directional one
    Rgb irradiance;   // before attenuation
};

// None for a point light exactly at x (no direction to come from), a point
// inside a sphere light, or a dark light. A sphere light's arrival comes from the
// direction (u, v) of its cone (uniform in solid angle, core/sphere_light.h)
// with the light of the whole cone: averaged over (u, v) it is the sphere's.
std::optional<LightArrival> lightArrivingAt(const Light& light, const Vec3& x, double u = 0.5, double v = 0.5);

// The reference integrates a sphere light's cone on this many strata per axis.
inline constexpr int kSphereLightStrata = 8;

// exp(-sum over objects of sigma_t times the density path) per channel.
Rgb transmittanceToLight(const std::vector<VolumeObject>& objects, const Vec3& x, const LightArrival& arrival);

// sum over the lights of p(w_light, dir) E T at x inside o, each light arriving
// through o's boundary (lightThroughBoundary) and dimmed inside o on its way to
// x: the light a collision at x scatters along dir, as both ground truths gather it.
Rgb lightsThroughBoundary(const VolumeObject& o, const std::vector<VolumeObject>& objects,
                          const std::vector<Light>& lights, const Vec3& x, const Vec3& dir);

// The same, estimated without bias by the path tracer at a collision: each
// light's solve runs with the odds boundarySolveOdds gives and what it finds
// is divided by them. uniform draws in [0, 1).
Rgb lightsThroughBoundaryByRoulette(const VolumeObject& o, const std::vector<VolumeObject>& objects,
                                    const std::vector<Light>& lights, const Vec3& x, const Vec3& dir,
                                    const std::function<double()>& uniform);
// The odds of solving for the light through o's boundary at x, in
// [kLeastSolveOdds, 1]: 1 where the straight line to the light keeps at least
// kSureSolveTransmittance of it inside o, in proportion below.
double boundarySolveOdds(const VolumeObject& o, const Light& light, const Vec3& x);
inline constexpr double kSureSolveTransmittance = 0.3;
inline constexpr double kLeastSolveOdds = 0.3;

}  // namespace lucent
