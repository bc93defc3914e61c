#include "bench/uncollided_quadrature.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace lucent {

namespace {

struct Unfolded {
    const TransportProblem& p;
    int mirror[3] = {0, 0, 0};  // -1: the min face reflects, +1: the max face, 0: neither
    std::vector<double> planes[3];

    explicit Unfolded(const TransportProblem& problem) : p(problem) {
        for (int a = 0; a < 3; ++a) {
            if (p.reflective[2 * a] && p.reflective[2 * a + 1])
                throw std::invalid_argument("uncollidedQuadrature: both faces of an axis are reflective");
            mirror[a] = p.reflective[2 * a] ? -1 : p.reflective[2 * a + 1] ? 1 : 0;
            std::vector<double> at{p.domain.min[a], p.domain.max[a]};
            for (const TransportRegion& r : p.regions) {
                at.push_back(r.box.min[a]);
                at.push_back(r.box.max[a]);
            }
            for (double v : at) {
                planes[a].push_back(v);
                if (mirror[a] != 0) planes[a].push_back(2.0 * face(a) - v);
            }
        }
    }
    double face(int a) const { return mirror[a] < 0 ? p.domain.min[a] : p.domain.max[a]; }
    Vec3 fold(Vec3 x) const {
        for (int a = 0; a < 3; ++a)
            if ((mirror[a] < 0 && x[a] < face(a)) || (mirror[a] > 0 && x[a] > face(a))) x[a] = 2.0 * face(a) - x[a];
        return x;
    }
    // The region holding x (the last), or null for vacuum and outside the domain.
    const TransportRegion* at(const Vec3& unfolded) const {
        const Vec3 x = fold(unfolded);
        if (!p.domain.contains(x)) return nullptr;
        const TransportRegion* in = nullptr;
        for (const TransportRegion& r : p.regions)
            if (r.box.contains(x)) in = &r;
        return in;
    }
    // Every source region and its mirror images, as one box.
    Bounds3 sources() const {
        Bounds3 all;
        for (const TransportRegion& r : p.regions) {
            if (r.source <= 0.0) continue;
            for (int mask = 0; mask < 8; ++mask) {
                Bounds3 b = r.box;
                bool skip = false;
                for (int a = 0; a < 3; ++a) {
                    if (!(mask >> a & 1)) continue;
                    if (mirror[a] == 0) skip = true;
                    const double lo = 2.0 * face(a) - b.max[a], hi = 2.0 * face(a) - b.min[a];
                    b.min[a] = lo;
                    b.max[a] = hi;
                }
                if (skip) continue;
                all.extend(b.min);
                all.extend(b.max);
            }
        }
        return all;
    }
    // int_0^end q e^{-tau} dt from x along w, exact between the planes.
    double emission(const Vec3& x, const Vec3& w, double end) const {
        std::vector<double> cuts{0.0, end};
        for (int a = 0; a < 3; ++a) {
            if (w[a] == 0.0) continue;
            for (double v : planes[a]) {
                const double t = (v - x[a]) / w[a];
                if (t > 0.0 && t < end) cuts.push_back(t);
            }
        }
        std::sort(cuts.begin(), cuts.end());
        double tau = 0.0, sum = 0.0;
        for (size_t i = 0; i + 1 < cuts.size(); ++i) {
            const double length = cuts[i + 1] - cuts[i];
            if (!(length > 0.0)) continue;
            const TransportRegion* r = at(x + w * (0.5 * (cuts[i] + cuts[i + 1])));
            const double sigma = r ? r->sigmaT : 0.0, q = r ? r->source : 0.0;
            if (q > 0.0)
                sum += q * std::exp(-tau) * (sigma * length > 1e-8 ? -std::expm1(-sigma * length) / sigma : length);
            tau += sigma * length;
        }
        return sum;
    }
};

}  // namespace

double uncollidedQuadrature(const TransportProblem& problem, const Vec3& x, int polar) {
    const Unfolded u(problem);
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
            if (clipToBox(box, x, w, t0, t1)) sum += u.emission(x, w, t1);
        }
    }
    return sum * ((1.0 - lowest) / polar) * (2.0 * kPi / azimuths) / (4.0 * kPi);
}

}  // namespace lucent
