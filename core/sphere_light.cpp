#include "core/sphere_light.h"

#include <algorithm>
#include <cmath>

namespace lucent {

std::optional<SphereLightCone> sphereLightCone(const Vec3& centre, double radius, const Vec3& x) {
    const Vec3 toCentre = centre - x;
    const double d = glm::length(toCentre);
    if (!(d > radius)) return std::nullopt;
    // 1 - cos = s^2 / (1 + sqrt(1 - s^2)) with s = R / d: no cancellation for small lights.
    const double s2 = (radius / d) * (radius / d);
    const double oneMinusCos = s2 / (1.0 + std::sqrt(1.0 - s2));
    return SphereLightCone{toCentre / d, 1.0 - oneMinusCos, d, 2.0 / (d * d * (1.0 + std::sqrt(1.0 - s2)))};
}

Vec3 coneDirection(const SphereLightCone& cone, double u, double v) {
    const double cosT = 1.0 - u * (1.0 - cone.cosMax);
    const double sinT = std::sqrt(std::max(0.0, 1.0 - cosT * cosT));
    const double phi = 2.0 * kPi * v;
    const Vec3& w = cone.axis;
    const Vec3 a = glm::normalize(std::abs(w.x) > 0.5 ? glm::cross(w, Vec3(0, 1, 0)) : glm::cross(w, Vec3(1, 0, 0)));
    const Vec3 b = glm::cross(w, a);
    return glm::normalize(cosT * w + sinT * (std::cos(phi) * a + std::sin(phi) * b));
}

std::vector<std::string> sphereLightsThroughBoundaries(const SceneDesc& scene) {
    std::vector<std::string> out;
    for (size_t j = 0; j < scene.lights.size(); ++j) {
        if (!(scene.lights[j].radius > 0.0)) continue;
        for (const ObjectDesc& o : scene.objects)
            if (o.medium.ior != 1.0)
                out.push_back("light " + std::to_string(j) +
                              " is a sphere: through the refracting boundary of object '" + o.name +
                              "' it is taken as a point at its centre (no soft shadows, no extent)");
    }
    return out;
}

double distanceToSphere(const Vec3& x, const Vec3& w, const Vec3& centre, double radius) {
    const Vec3 toCentre = centre - x;
    const double along = glm::dot(toCentre, w);
    const double miss2 = std::max(0.0, glm::dot(toCentre, toCentre) - along * along);
    const double inside = radius * radius - miss2;
    return inside > 0.0 ? along - std::sqrt(inside) : along;
}

}  // namespace lucent
