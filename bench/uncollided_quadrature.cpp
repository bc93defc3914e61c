#include "bench/uncollided_quadrature.h"

#include <cmath>

#include "bench/unfolded_problem.h"

namespace lucent {

namespace {

// int_0^end q e^{-tau} dt from x along w, exact between the planes.
double emission(const UnfoldedProblem& u, const Vec3& x, const Vec3& w, double end) {
    double tau = 0.0, sum = 0.0;
    u.walk(x, w, end, [&](const TransportRegion* r, double t0, double t1) {
        const double length = t1 - t0, sigma = r ? r->sigmaT : 0.0, q = r ? r->source : 0.0;
        if (q > 0.0)
            sum += q * std::exp(-tau) * (sigma * length > 1e-8 ? -std::expm1(-sigma * length) / sigma : length);
        tau += sigma * length;
    });
    return sum;
}

}  // namespace

double uncollidedQuadrature(const TransportProblem& problem, const Vec3& x, int polar) {
    const UnfoldedProblem u(problem);
    const Bounds3 box = u.sources();
    if (!(box.min.x <= box.max.x)) return 0.0;
    // The cone about the direction to the sources' centre that holds all
    // their corners (a convex box lies in it), or the sphere from inside.
    const Vec3 axis = box.center() - x;
    double lowest = -1.0;
    Vec3 z(0, 0, 1);
    if (!box.contains(x) && glm::length(axis) > 0.0) {
        z = glm::normalize(axis);
        lowest = 1.0;
        for (int c = 0; c < 8; ++c) {
            const Vec3 corner(c & 1 ? box.max.x : box.min.x, c & 2 ? box.max.y : box.min.y,
                              c & 4 ? box.max.z : box.min.z);
            lowest = std::min(lowest, glm::dot(glm::normalize(corner - x), z));
        }
    }
    const Vec3 helper = std::abs(z.x) < 0.9 ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
    const Vec3 e1 = glm::normalize(glm::cross(helper, z)), e2 = glm::cross(z, e1);
    const int azimuths = 2 * polar;
    double sum = 0.0;
    for (int i = 0; i < polar; ++i) {
        const double mu = lowest + (i + 0.5) * (1.0 - lowest) / polar, s = std::sqrt(std::max(0.0, 1.0 - mu * mu));
        for (int j = 0; j < azimuths; ++j) {
            const double phi = (j + 0.5) * 2.0 * kPi / azimuths;
            const Vec3 w = e1 * (s * std::cos(phi)) + e2 * (s * std::sin(phi)) + z * mu;
            double t0 = 0.0, t1 = kInfinity;
            if (clipToBox(box, x, w, t0, t1)) sum += emission(u, x, w, t1);
        }
    }
    return sum * ((1.0 - lowest) / polar) * (2.0 * kPi / azimuths) / (4.0 * kPi);
}

}  // namespace lucent
