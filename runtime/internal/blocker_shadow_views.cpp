#include "runtime/internal/blocker_shadow_views.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace lucent {
namespace {

glm::mat4 cubeFaceView(const glm::vec3& eye, int face) {
    glm::vec3 axis(0.0f);
    axis[face / 2] = face % 2 ? -1.0f : 1.0f;
    const glm::vec3 up = face / 2 == 1 ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0);
    return glm::lookAt(eye, eye + axis, up);
}

}  // namespace

int blockerShadowLayers(size_t lightCount) { return std::max<int>(6 * int(lightCount), 6); }

int blockerShadowResolution(size_t lightCount) {
    if (lightCount <= 4) return 512;
    return std::max(64, int(512.0 * std::sqrt(4.0 / double(lightCount))));
}

int entryMapResolution(size_t lightCount) {
    if (lightCount <= 1) return 512;
    return std::max(32, int(512.0 / std::sqrt(double(lightCount))));
}

const Light* layerLight(const std::vector<Light>& lights, int layer) {
    const size_t j = size_t(layer / 6);
    if (layer < 0 || j >= lights.size()) return nullptr;
    if (lights[j].type == Light::Type::Directional && layer % 6 != 0) return nullptr;
    return &lights[j];
}

glm::vec4 packedLight(const Light& light) {
    return light.type == Light::Type::Point ? glm::vec4(glm::vec3(light.position), 1.0f)
                                            : glm::vec4(glm::normalize(glm::vec3(light.direction)), 0.0f);
}

Bounds3 placedBox(const Bounds3& box, const Similarity& placement) {
    Bounds3 world;
    for (int corner = 0; corner < 8; ++corner)
        world.extend(placement.point(Vec3(corner & 1 ? box.max.x : box.min.x, corner & 2 ? box.max.y : box.min.y,
                                          corner & 4 ? box.max.z : box.min.z)));
    return world;
}

std::vector<glm::mat4> blockerShadowViews(const std::vector<Light>& lights, const Bounds3& blockerBounds) {
    const glm::vec3 centre(blockerBounds.center());
    const float radius = std::max(float(0.5 * blockerBounds.diagonal()), 1e-6f);
    std::vector<glm::mat4> views(size_t(blockerShadowLayers(lights.size())), glm::mat4(1.0f));
    for (size_t j = 0; j < lights.size(); ++j) {
        const Light& l = lights[j];
        if (l.type == Light::Type::Point) {
            const glm::vec3 eye(l.position);
            const float farPlane = glm::length(centre - eye) + radius;
            const glm::mat4 projection =
                glm::perspective(glm::radians(90.0f), 1.0f, farPlane * 1e-5f, farPlane * 1.01f);
            for (int face = 0; face < 6; ++face) views[6 * j + face] = projection * cubeFaceView(eye, face);
        } else {
            // Looking along the light from outside the sphere; the map stores dot(x, d).
            const glm::vec3 d = glm::normalize(glm::vec3(l.direction));
            const glm::vec3 up = std::abs(d.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
            const glm::mat4 view = glm::lookAt(centre - 2.0f * radius * d, centre, up);
            views[6 * j] = glm::ortho(-radius, radius, -radius, radius, 0.5f * radius, 3.5f * radius) * view;
        }
    }
    return views;
}

}  // namespace lucent
