#pragma once
// Pinhole camera rays: pixel (x, y) with row 0 at the top looks through the
// centre of its square, as a rasteriser with the same view and projection does.
#include "core/math.h"
#include "core/scene.h"

namespace lucent {

class CameraRays {
public:
    explicit CameraRays(const Camera& camera) : origin_(camera.position) {
        forward_ = glm::normalize(camera.target - camera.position);
        right_ = glm::normalize(glm::cross(forward_, camera.up));
        up_ = glm::cross(right_, forward_);
        halfHeight_ = std::tan(0.5 * camera.fovYDegrees * kPi / 180.0);
        halfWidth_ = halfHeight_ * double(camera.width) / double(camera.height);
        width_ = camera.width;
        height_ = camera.height;
    }
    const Vec3& origin() const { return origin_; }
    // Unit direction through image position (px, py) in pixels, (0, 0) the top-left corner.
    Vec3 direction(double px, double py) const {
        const double u = (2.0 * px / width_ - 1.0) * halfWidth_;
        const double v = (1.0 - 2.0 * py / height_) * halfHeight_;
        return glm::normalize(forward_ + u * right_ + v * up_);
    }

private:
    Vec3 origin_, forward_, right_, up_;
    double halfWidth_, halfHeight_;
    int width_, height_;
};

}  // namespace lucent
