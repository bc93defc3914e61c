#pragma once
// The camera as the OpenGL passes take it: view and projection matrices that
// match core's CameraRays for the same camera, with near and far planes hugging
// the scene so that depth keeps its precision. Pure math, no GL.
#include <glm/glm.hpp>

#include "core/math.h"
#include "core/scene.h"

namespace lucent {

struct ViewSetup {
    glm::mat4 view{1.0f};
    glm::mat4 projection{1.0f};
    glm::vec3 cameraPosition{0.0f};
    int width = 0, height = 0;
};

ViewSetup viewSetupFor(const Camera& camera, const Bounds3& sceneBounds);

}  // namespace lucent
