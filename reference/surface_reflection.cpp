#include "reference/surface_reflection.h"

#include <algorithm>
#include <cmath>

namespace lucent {

Rgb phongSurfaceReflection(const SurfaceDesc& s, const std::vector<Light>& lights, const Vec3& x, const Vec3& n,
                           const Vec3& viewDir) {
    Rgb sum(0.0);
    const Vec3 toEye = -viewDir;
    for (const Light& light : lights) {
        Vec3 toLight = light.type == Light::Type::Point ? light.position - x : -light.direction;
        const double d2 = light.type == Light::Type::Point ? glm::dot(toLight, toLight) : 1.0;
        if (d2 == 0.0) continue;
        toLight = glm::normalize(toLight);
        const double cone = spotFalloff(light, -toLight);
        const double cosI = glm::dot(n, toLight);
        if (cosI <= 0.0) continue;
        const Vec3 reflected = 2.0 * cosI * n - toLight;
        const double cosR = std::max(0.0, glm::dot(reflected, toEye));
        // Energy-normalised Phong BRDF times irradiance.
        const Rgb brdf = s.diffuse / kPi + s.specular * (s.shininess + 2.0) / (2.0 * kPi) * std::pow(cosR, s.shininess);
        sum += brdf * light.power * (cone / d2 * cosI);
    }
    return sum;
}

Rgb firstSurfaceReflection(const std::vector<VolumeObject>& objects, const std::vector<Light>& lights,
                           const Vec3& origin, const Vec3& dir, double tStop) {
    Rgb surface(0.0);
    double nearest = kInfinity;
    std::vector<Crossing> crossings;
    for (const VolumeObject& o : objects) {
        if (!o.desc().surface) continue;
        o.boundary().crossings(origin, dir, crossings);
        if (!crossings.empty() && !crossings.front().exits && crossings.front().t < std::min(nearest, tStop)) {
            nearest = crossings.front().t;
            const Vec3 hit = origin + nearest * dir;
            surface = phongSurfaceReflection(*o.desc().surface, lights, hit,
                                             o.shadingNormal(crossings.front().face, hit), dir);
        }
    }
    return surface;
}

}  // namespace lucent
