#include "core/sphere_directions.h"

#include <cmath>

namespace lucent {

std::vector<Vec3> fibonacciSphere(int n) {
    std::vector<Vec3> dirs(n);
    const double goldenAngle = kPi * (3.0 - std::sqrt(5.0));
    for (int i = 0; i < n; ++i) {
        const double z = 1.0 - (2.0 * i + 1.0) / n;  // cell centres in z: equal areas
        const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
        const double phi = goldenAngle * i;
        dirs[i] = Vec3(r * std::cos(phi), r * std::sin(phi), z);
    }
    return dirs;
}

glm::dmat3 randomRotation(Rng& rng) {
    // Shoemake's uniform random unit quaternion.
    const double u1 = rng.uniform(), u2 = 2 * kPi * rng.uniform(), u3 = 2 * kPi * rng.uniform();
    const double a = std::sqrt(1 - u1), b = std::sqrt(u1);
    const double w = a * std::sin(u2), x = a * std::cos(u2), y = b * std::sin(u3), z = b * std::cos(u3);
    return glm::dmat3(1 - 2 * (y * y + z * z), 2 * (x * y + w * z), 2 * (x * z - w * y), 2 * (x * y - w * z),
                      1 - 2 * (x * x + z * z), 2 * (y * z + w * x), 2 * (x * z + w * y), 2 * (y * z - w * x),
                      1 - 2 * (x * x + y * y));
}

}  // namespace lucent
