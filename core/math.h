#pragma once
// Vector types and constants shared by every stage. Geometry runs in double
// precision on the CPU; only the GPU path (later) drops to float.
#include <algorithm>
#include <cmath>
#include <utility>
#include <glm/glm.hpp>

namespace lucent {

using Vec2 = glm::dvec2;
using Vec3 = glm::dvec3;
using Rgb = glm::dvec3;

inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kInvFourPi = 1.0 / (4.0 * kPi);
inline constexpr double kInfinity = HUGE_VAL;

inline bool isFinite(const Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

struct Bounds3 {
    Vec3 min{kInfinity};
    Vec3 max{-kInfinity};
    void extend(const Vec3& p) {
        min = glm::min(min, p);
        max = glm::max(max, p);
    }
    Vec3 extent() const { return max - min; }
    Vec3 center() const { return 0.5 * (min + max); }
    double diagonal() const { return glm::length(max - min); }
    bool contains(const Vec3& p) const {
        return p.x >= min.x && p.y >= min.y && p.z >= min.z && p.x <= max.x && p.y <= max.y && p.z <= max.z;
    }
};

// Clips [t0, t1] to the parameters at which origin + t dir lies in box (the
// slab test); false when nothing is left. A zero component of dir keeps the
// whole range if origin lies between that axis' planes, else nothing.
inline bool clipToBox(const Bounds3& box, const Vec3& origin, const Vec3& dir, double& t0, double& t1) {
    for (int a = 0; a < 3; ++a) {
        if (dir[a] == 0.0) {
            if (origin[a] < box.min[a] || origin[a] > box.max[a]) return false;
            continue;
        }
        double lo = (box.min[a] - origin[a]) / dir[a], hi = (box.max[a] - origin[a]) / dir[a];
        if (lo > hi) std::swap(lo, hi);
        t0 = std::max(t0, lo);
        t1 = std::min(t1, hi);
    }
    return t0 < t1;
}

// Henyey-Greenstein phase function, normalised over the sphere; g = 0 gives 1/(4 pi).
// cosTheta is the cosine between the propagation directions of incident and scattered light.
inline double henyeyGreenstein(double cosTheta, double g) {
    double denom = 1.0 + g * g - 2.0 * g * cosTheta;
    denom = std::max(denom, 1e-12);
    return kInvFourPi * (1.0 - g * g) / (denom * std::sqrt(denom));
}

}  // namespace lucent
