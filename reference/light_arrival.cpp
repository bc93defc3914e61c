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

Rgb lightsThroughBoundary(const VolumeObject& o, const std::vector<VolumeObject>& objects,
                          const std::vector<Light>& lights, const Vec3& x, const Vec3& dir) {
    Rgb sum(0.0);
    for (const Light& light : lights) {
        const std::optional<RefractedArrival> a = lightThroughBoundary(o, light, x);
        if (!a) continue;
        Rgb outside(1.0);
        for (const VolumeObject& other : objects)
            if (&other != &o)
                outside *=
                    transmittance(other.desc().medium.sigmaT, other.densityPath(a->entry, a->outward, a->outside));
        sum += henyeyGreenstein(glm::dot(a->toLight, dir), o.desc().medium.g) * a->irradiance * outside *
               transmittance(o.desc().medium.sigmaT, o.densityPath(x, a->toLight, a->inside));
    }
    return sum;
}

}  // namespace lucent
