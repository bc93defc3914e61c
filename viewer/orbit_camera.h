#pragma once
// The viewer's camera: orbits a target at a distance, pans it, zooms.
#include <algorithm>
#include <cmath>

#include "core/scene.h"

namespace lucent {

class OrbitCamera {
public:
    explicit OrbitCamera(const Camera& start) : camera_(start) {
        const Vec3 offset = start.position - start.target;
        distance_ = glm::length(offset);
        yaw_ = std::atan2(offset.x, offset.z);
        pitch_ = std::asin(std::clamp(offset.y / distance_, -1.0, 1.0));
    }
    void orbit(double yawDegrees, double pitchDegrees) {
        yaw_ += glm::radians(yawDegrees);
        pitch_ = std::clamp(pitch_ + glm::radians(pitchDegrees), -1.55, 1.55);
    }
    void zoom(double factor) { distance_ = std::max(distance_ * factor, 1e-6); }
    // Moves the target in the view plane by fractions of the distance.
    void pan(double right, double up) {
        const Camera c = camera();
        const Vec3 forward = glm::normalize(c.target - c.position);
        const Vec3 r = glm::normalize(glm::cross(forward, Vec3(0, 1, 0)));
        const Vec3 u = glm::cross(r, forward);
        camera_.target += distance_ * (right * r + up * u);
    }
    Camera camera() const {
        Camera c = camera_;
        c.up = Vec3(0, 1, 0);
        c.position = camera_.target + distance_ * Vec3(std::cos(pitch_) * std::sin(yaw_), std::sin(pitch_),
                                                       std::cos(pitch_) * std::cos(yaw_));
        return c;
    }
    void resize(int width, int height) {
        camera_.width = width;
        camera_.height = height;
    }

private:
    Camera camera_;
    double distance_, yaw_, pitch_;
};

}  // namespace lucent
