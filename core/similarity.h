#pragma once
// Where an object stands in the scene: a uniform scale, then a rotation, then a
// translation (the scene's "transform", docs/scene-file.md). Only similarities:
// a sample file stores each sample's attenuation exp(-tau) over directions, and
// under a uniform scale s every optical depth becomes s tau, so the stored
// psi becomes psi^s exactly; a non-uniform scale would stretch tau differently
// per direction, which no sample file holds. Rigid motion changes nothing but
// where the samples are and which way their directions point.
#include <glm/glm.hpp>

#include "core/math.h"

namespace lucent {

struct Similarity {
    double scale = 1.0;
    glm::dmat3 rotation{1.0};  // proper rotation (det +1), columns the object's axes in the world
    Vec3 translation{0.0};

    bool operator==(const Similarity& o) const {
        return scale == o.scale && rotation == o.rotation && translation == o.translation;
    }
    bool isIdentity() const { return *this == Similarity{}; }
    // Object space to world space.
    Vec3 point(const Vec3& p) const { return translation + scale * (rotation * p); }
    Vec3 direction(const Vec3& d) const { return rotation * d; }
    // World space to object space.
    Vec3 inversePoint(const Vec3& p) const { return glm::transpose(rotation) * (p - translation) / scale; }
    Vec3 inverseDirection(const Vec3& d) const { return glm::transpose(rotation) * d; }
    // The 4x4 model matrix (column-major, as OpenGL takes it).
    glm::dmat4 matrix() const;
};

// scale, then a rotation of degrees about axis (right-handed; axis any length
// but zero), then translate.
Similarity makeSimilarity(double scale, const Vec3& axis, double degrees, const Vec3& translate);

}  // namespace lucent
