#include "core/similarity.h"

namespace lucent {

glm::dmat4 Similarity::matrix() const {
    glm::dmat4 m(scale * rotation);
    m[3] = glm::dvec4(translation, 1.0);
    return m;
}

Similarity makeSimilarity(double scale, const Vec3& axis, double degrees, const Vec3& translate) {
    // Rodrigues' formula: R = cos a I + sin a [k]x + (1 - cos a) k k^T.
    const Vec3 k = glm::normalize(axis);
    const double a = degrees * kPi / 180.0, c = std::cos(a), s = std::sin(a);
    glm::dmat3 r(c);
    const glm::dmat3 cross(0.0, k.z, -k.y, -k.z, 0.0, k.x, k.y, -k.x, 0.0);  // columns of [k]x
    r += s * cross + (1.0 - c) * glm::outerProduct(k, k);
    Similarity t;
    t.scale = scale;
    t.rotation = r;
    t.translation = translate;
    return t;
}

}  // namespace lucent
