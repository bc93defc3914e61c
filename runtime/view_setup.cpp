#include "runtime/view_setup.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>

namespace lucent {

ViewSetup viewSetupFor(const Camera& camera, const Bounds3& sceneBounds) {
    ViewSetup v;
    v.width = camera.width;
    v.height = camera.height;
    v.cameraPosition = glm::vec3(camera.position);
    v.view = glm::lookAt(camera.position, camera.target, camera.up);
    const double radius = 0.5 * sceneBounds.diagonal();
    const double distance = glm::length(sceneBounds.center() - camera.position);
    const double farPlane = distance + 2.0 * radius + 1e-6;
    const double nearPlane = std::max(distance - 2.0 * radius, farPlane * 1e-5);
    v.projection =
        glm::perspective(glm::radians(camera.fovYDegrees), double(camera.width) / camera.height, nearPlane, farPlane);
    return v;
}

}  // namespace lucent
