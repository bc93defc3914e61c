#pragma once
// A `lucent transport` problem with its reflective faces unfolded: beyond a
// mirror, the medium and the sources are the mirror image of the domain's
// (one reflective face per axis at most), so that light reflected on its way
// from one point to another runs straight from an image of the first. Shared
// by the truths computed without the solver's cells (uncollided_quadrature.h,
// collided_monte_carlo.h).
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "core/transport_problem.h"

namespace lucent {

class UnfoldedProblem {
public:
    explicit UnfoldedProblem(const TransportProblem& problem) : p_(problem) {
        for (int a = 0; a < 3; ++a) {
            if (p_.reflective[2 * a] && p_.reflective[2 * a + 1])
                throw std::invalid_argument("a transport problem unfolded: both faces of an axis are reflective");
            mirror_[a] = p_.reflective[2 * a] ? -1 : p_.reflective[2 * a + 1] ? 1 : 0;
            std::vector<double> at{p_.domain.min[a], p_.domain.max[a]};
            for (const TransportRegion& r : p_.regions) {
                at.push_back(r.box.min[a]);
                at.push_back(r.box.max[a]);
            }
            for (double v : at) {
                planes_[a].push_back(v);
                if (mirror_[a] != 0) planes_[a].push_back(2.0 * face(a) - v);
            }
            std::sort(planes_[a].begin(), planes_[a].end());
            planes_[a].erase(std::unique(planes_[a].begin(), planes_[a].end()), planes_[a].end());
        }
        for (const TransportRegion& r : p_.regions) {
            if (r.source <= 0.0) continue;
            for (const Vec3& corner : images(r.box.min)) sources_.extend(corner);
            for (const Vec3& corner : images(r.box.max)) sources_.extend(corner);
        }
    }
    const TransportProblem& problem() const { return p_; }
    double face(int a) const { return mirror_[a] < 0 ? p_.domain.min[a] : p_.domain.max[a]; }
    // The domain with its mirror images: where the unfolded medium is.
    Bounds3 unfoldedDomain() const {
        Bounds3 b = p_.domain;
        for (int a = 0; a < 3; ++a) {
            if (mirror_[a] < 0) b.min[a] = 2.0 * face(a) - p_.domain.max[a];
            if (mirror_[a] > 0) b.max[a] = 2.0 * face(a) - p_.domain.min[a];
        }
        return b;
    }
    Vec3 fold(Vec3 x) const {
        for (int a = 0; a < 3; ++a)
            if ((mirror_[a] < 0 && x[a] < face(a)) || (mirror_[a] > 0 && x[a] > face(a))) x[a] = 2.0 * face(a) - x[a];
        return x;
    }
    // The region holding x (the last), or null for vacuum and outside the domain.
    const TransportRegion* at(const Vec3& unfolded) const {
        const Vec3 x = fold(unfolded);
        if (!p_.domain.contains(x)) return nullptr;
        const TransportRegion* in = nullptr;
        for (const TransportRegion& r : p_.regions)
            if (r.box.contains(x)) in = &r;
        return in;
    }
    // Every source region and its mirror images, as one box.
    const Bounds3& sources() const { return sources_; }
    // The cone from x that holds every source and its mirror images (a convex
    // box lies in the cone of its corners), or the whole sphere from among them.
    struct Cone {
        Vec3 axis, e1, e2;  // an orthonormal frame about the axis
        double lowest;      // the cosine of the half-angle: -1 for the sphere
        Vec3 direction(double mu, double phi) const {
            const double s = std::sqrt(std::max(0.0, 1.0 - mu * mu));
            return e1 * (s * std::cos(phi)) + e2 * (s * std::sin(phi)) + axis * mu;
        }
    };
    Cone sourceCone(const Vec3& x) const {
        const Bounds3& box = sources_;
        Cone c{Vec3(0, 0, 1), {}, {}, -1.0};
        if (box.min.x <= box.max.x && !box.contains(x) && glm::length(box.center() - x) > 0.0) {
            c.axis = glm::normalize(box.center() - x);
            c.lowest = 1.0;
            for (int k = 0; k < 8; ++k) {
                const Vec3 corner(k & 1 ? box.max.x : box.min.x, k & 2 ? box.max.y : box.min.y,
                                  k & 4 ? box.max.z : box.min.z);
                c.lowest = std::min(c.lowest, glm::dot(glm::normalize(corner - x), c.axis));
            }
        }
        const Vec3 helper = std::abs(c.axis.x) < 0.9 ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
        c.e1 = glm::normalize(glm::cross(helper, c.axis));
        c.e2 = glm::cross(c.axis, c.e1);
        return c;
    }
    // int q e^{-tau} dt from x along w until the ray leaves the sources' box,
    // exact between the planes: the sources' uncollided radiance arriving at x
    // from -w.
    double emission(const Vec3& x, const Vec3& w) const {
        double t0 = 0.0, end = kInfinity;
        if (!clipToBox(sources(), x, w, t0, end)) return 0.0;
        double tau = 0.0, sum = 0.0;
        walk(x, w, end, [&](const TransportRegion* r, double a, double b) {
            const double length = b - a, sigma = r ? r->sigmaT : 0.0, q = r ? r->source : 0.0;
            if (q > 0.0)
                sum += q * std::exp(-tau) * (sigma * length > 1e-8 ? -std::expm1(-sigma * length) / sigma : length);
            tau += sigma * length;
        });
        return sum;
    }
    // Calls piece(region or null, t0, t1) for each stretch [t0, t1] of x + t w,
    // 0 <= t <= end, over which the medium is constant, in order.
    template <typename Piece>
    void walk(const Vec3& x, const Vec3& w, double end, Piece&& piece) const {
        thread_local std::vector<double> cuts;
        cuts.assign({0.0, end});
        for (int a = 0; a < 3; ++a) {
            if (w[a] == 0.0) continue;
            for (double v : planes_[a]) {
                const double t = (v - x[a]) / w[a];
                if (t > 0.0 && t < end) cuts.push_back(t);
            }
        }
        std::sort(cuts.begin(), cuts.end());
        for (size_t i = 0; i + 1 < cuts.size(); ++i)
            if (cuts[i + 1] > cuts[i]) piece(at(x + w * (0.5 * (cuts[i] + cuts[i + 1]))), cuts[i], cuts[i + 1]);
    }

private:
    // The point's images across every combination of the mirrors (itself first).
    std::vector<Vec3> images(const Vec3& x) const {
        std::vector<Vec3> out;
        for (int mask = 0; mask < 8; ++mask) {
            Vec3 y = x;
            bool skip = false;
            for (int a = 0; a < 3; ++a) {
                if (!(mask >> a & 1)) continue;
                if (mirror_[a] == 0) skip = true;
                y[a] = 2.0 * face(a) - y[a];
            }
            if (!skip) out.push_back(y);
        }
        return out;
    }

    const TransportProblem& p_;
    int mirror_[3] = {0, 0, 0};  // per axis: -1, its min face reflects; +1, its max face; 0, neither
    std::vector<double> planes_[3];
    Bounds3 sources_;
};

}  // namespace lucent
