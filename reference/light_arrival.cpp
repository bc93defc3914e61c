#include "reference/light_arrival.h"

#include <algorithm>
#include <cmath>

#include "core/sphere_light.h"

namespace lucent {

std::optional<LightArrival> lightArrivingAt(const Light& light, const Vec3& x, double u, double v) {
    LightArrival a;
    if (light.type == Light::Type::Point && light.radius > 0.0) {
        const std::optional<SphereLightCone> cone = sphereLightCone(light.position, light.radius, x);
        if (!cone) return std::nullopt;
        a.toLight = coneDirection(*cone, u, v);
        a.distance = distanceToSphere(x, a.toLight, light.position, light.radius);
        a.irradiance = light.power * cone->irradiance;
    } else if (light.type == Light::Type::Point) {
        a.toLight = light.position - x;
        a.distance = glm::length(a.toLight);
        if (a.distance == 0.0) return std::nullopt;
        a.toLight /= a.distance;
        a.irradiance = light.power * (spotFalloff(light, -a.toLight) / (a.distance * a.distance));
    } else {
        a.toLight = -light.direction;
        a.distance = kInfinity;
        a.irradiance = light.power;
    }
    if (std::max({std::abs(a.irradiance.r), std::abs(a.irradiance.g), std::abs(a.irradiance.b)}) == 0.0)
        return std::nullopt;
    return a;
}

Rgb transmittanceToLight(const std::vector<VolumeObject>& objects, const Vec3& x, const LightArrival& arrival) {
    // Each object attenuates with its own sigma_t; a scene of one object is the common case.
    Rgb transmitted(1.0);
    for (const VolumeObject& o : objects)
        transmitted *= transmittance(o.desc().medium.sigmaT, o.densityPath(x, arrival.toLight, arrival.distance));
    return transmitted;
}

namespace {

// One light's term of lightsThroughBoundary.
Rgb lightThroughBoundaryScattered(const VolumeObject& o, const std::vector<VolumeObject>& objects, const Light& light,
                                  const Vec3& x, const Vec3& dir) {
    const std::optional<RefractedArrival> a = lightThroughBoundary(o, light, x);
    if (!a) return Rgb(0.0);
    Rgb outside(1.0);
    for (const VolumeObject& other : objects)
        if (&other != &o)
            outside *= transmittance(other.desc().medium.sigmaT, other.densityPath(a->entry, a->outward, a->outside));
    return henyeyGreenstein(glm::dot(a->toLight, dir), o.desc().medium.g) * a->irradiance * outside *
           transmittance(o.desc().medium.sigmaT, o.densityPath(x, a->toLight, a->inside));
}

}  // namespace

Rgb lightsThroughBoundary(const VolumeObject& o, const std::vector<VolumeObject>& objects,
                          const std::vector<Light>& lights, const Vec3& x, const Vec3& dir) {
    Rgb sum(0.0);
    for (const Light& light : lights) sum += lightThroughBoundaryScattered(o, objects, light, x, dir);
    return sum;
}

// The solve costs about 18 ray casts where a straight shadow ray costs one
// (docs/accuracy.md, Refracting boundaries), and deep inside, far from the
// light along the straight line, what it finds is dimmed about as much as the
// line is: there the solve is skipped more often. The least odds bound the
// weight of what is found (1 / 0.3) where the refracted way is much clearer
// than the straight one.
double boundarySolveOdds(const VolumeObject& o, const Light& light, const Vec3& x) {
    if (light.type == Light::Type::Point && light.position == x) return 1.0;  // no direction to it
    const Rgb s = o.desc().medium.sigmaT;
    const double straight = std::exp(-std::min({s.r, s.g, s.b}) * o.densityPath(x, towardLight(light, x)));
    return std::clamp(straight / kSureSolveTransmittance, kLeastSolveOdds, 1.0);
}

Rgb lightsThroughBoundaryByRoulette(const VolumeObject& o, const std::vector<VolumeObject>& objects,
                                    const std::vector<Light>& lights, const Vec3& x, const Vec3& dir,
                                    const std::function<double()>& uniform) {
    Rgb sum(0.0);
    for (const Light& light : lights) {
        const double odds = boundarySolveOdds(o, light, x);
        if (odds < 1.0 && uniform() >= odds) continue;
        sum += lightThroughBoundaryScattered(o, objects, light, x, dir) / odds;
    }
    return sum;
}

}  // namespace lucent
