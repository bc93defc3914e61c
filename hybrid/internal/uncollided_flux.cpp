#include "hybrid/internal/uncollided_flux.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>

#include <tbb/parallel_for.h>

#include "core/spherical_harmonics.h"

namespace lucent::hybrid {

namespace {

using Cell = std::array<int, 3>;

struct SourceCell {
    Cell at;
    double q;  // source density times the cell's volume: particles per unit time
};

// The gathering of one problem: the grid, its near range and the harmonics' signs.
struct Gather {
    const DomGrid& grid;
    int bands, moments;
    Cell near{};                              // cells per axis within which a pair is near
    std::array<std::vector<double>, 8> sign;  // Y_m of a direction mirrored in the axes of bit mask / Y_m of it

    size_t index(const Cell& c) const { return grid.index()(c); }
    glm::dvec3 extinction(const Cell& c) const { return glm::dvec3(glm::vec3(grid.extinction[index(c)])); }
    bool isNear(const Cell& d) const {
        return std::abs(d[0]) <= near[0] && std::abs(d[1]) <= near[1] && std::abs(d[2]) <= near[2];
    }

    // The optical depth (rgb) between the centres of cells a and b, every
    // cell between them crossed for its own length (Amanatides and Woo's traversal).
    glm::dvec3 opticalDepth(const Cell& a, const Cell& b) const {
        const Vec3 span = Vec3(b[0] - a[0], b[1] - a[1], b[2] - a[2]) * grid.edges;
        const double length = glm::length(span);
        Cell c = a;
        int step[3];
        double next[3], delta[3];
        for (int k = 0; k < 3; ++k) {
            step[k] = b[k] > a[k] ? 1 : -1;
            delta[k] = b[k] != a[k] ? grid.edges[k] / std::abs(span[k]) : kInfinity;  // of the segment, per cell
            next[k] = 0.5 * delta[k];
        }
        glm::dvec3 tau(0.0);
        double t = 0.0;
        while (true) {
            const int k = next[0] <= next[1] && next[0] <= next[2] ? 0 : next[1] <= next[2] ? 1 : 2;
            const double end = std::min(next[k], 1.0);
            tau += extinction(c) * ((end - t) * length);
            if (end >= 1.0 || c == b) break;
            t = end;
            c[k] += step[k];
            next[k] += delta[k];
        }
        return tau;
    }
};

// The kernel of a near pair: for cells d apart (d >= 0 on every axis), in a
// uniform medium of extinction sigma,
//   K_m = 1/V int_source int_target e^{-sigma r} / (4 pi r^2) Y_m(u / r) dx dy,  u = x - y, r = |u|,
// which is the target's average uncollided flux moment per unit source density.
// With A(u) = prod_a max(0, h_a - |u_a - d_a h_a|), the volume of pairs with
// difference u, and polar coordinates about u = 0 (r^2 dr cancels the 1 / r^2),
//   K_m = 1 / (4 pi V) int_sphere Y_m(omega) int_0^inf A(r omega) e^{-sigma r} dr d omega,
// no longer singular at r = 0. A is a product of three tents: cubic in r
// between the kinks where a component crosses d_a h_a or d_a h_a +- h_a, so
// four Gauss points per piece are exact but for the exponential, which the
// pieces are cut small enough for.
std::vector<double> nearKernel(const Cell& d, double sigma, const Vec3& h, int bands) {
    constexpr int kPolar = 96, kAzimuth = 192;
    static const double gx[4] = {-0.8611363115940526, -0.3399810435848563, 0.3399810435848563, 0.8611363115940526};
    static const double gw[4] = {0.3478548451374538, 0.6521451548625461, 0.6521451548625461, 0.3478548451374538};
    const int moments = bands * bands;
    std::vector<double> k(moments, 0.0), y(moments);
    const double volume = h.x * h.y * h.z;
    for (int i = 0; i < kPolar; ++i) {
        // The polar cosine by the midpoint rule: the integrand's kinks make Gauss no better.
        const double mu = -1.0 + (i + 0.5) * 2.0 / kPolar, s = std::sqrt(1.0 - mu * mu);
        for (int j = 0; j < kAzimuth; ++j) {
            const double phi = (j + 0.5) * 2.0 * kPi / kAzimuth;
            const Vec3 w(s * std::cos(phi), s * std::sin(phi), mu);
            // Where every tent is positive: r w_a within (d_a - 1, d_a + 1) h_a.
            double lo = 0.0, hi = kInfinity;
            std::array<double, 5> kinks;
            int count = 0;
            bool none = false;
            for (int a = 0; a < 3; ++a) {
                if (w[a] == 0.0) {
                    none = none || d[a] != 0;
                    continue;
                }
                const double r0 = (d[a] - 1) * h[a] / w[a], r1 = (d[a] + 1) * h[a] / w[a];
                lo = std::max(lo, std::min(r0, r1));
                hi = std::min(hi, std::max(r0, r1));
                kinks[count++] = d[a] * h[a] / w[a];
            }
            if (none || !(hi > lo)) continue;
            // Past e^{-50} of the nearest point nothing is left.
            if (sigma > 0.0) hi = std::min(hi, lo + 50.0 / sigma);
            kinks[count++] = lo;
            kinks[count++] = hi;
            for (int p = 1; p < count; ++p)  // insertion sort of at most five
                for (int q = p; q > 0 && kinks[q - 1] > kinks[q]; --q) std::swap(kinks[q - 1], kinks[q]);
            double radial = 0.0;
            for (int p = 0; p + 1 < count; ++p) {
                const double a = std::max(kinks[p], lo), b = std::min(kinks[p + 1], hi);
                if (!(b > a)) continue;
                const int cuts = std::clamp(int(std::ceil(sigma * (b - a) / 0.5)), 1, 200);
                const double piece = (b - a) / cuts;
                for (int c = 0; c < cuts; ++c)
                    for (int g = 0; g < 4; ++g) {
                        const double r = a + piece * (c + 0.5 + 0.5 * gx[g]);
                        double area = 1.0;
                        for (int e = 0; e < 3; ++e) area *= std::max(0.0, h[e] - std::abs(r * w[e] - d[e] * h[e]));
                        radial += 0.5 * piece * gw[g] * area * std::exp(-sigma * r);
                    }
            }
            if (radial == 0.0) continue;
            evaluateSh(bands, w, y);
            const double weight = radial * (2.0 / kPolar) * (2.0 * kPi / kAzimuth) / (4.0 * kPi * volume);
            for (int m = 0; m < moments; ++m) k[m] += weight * y[m];
        }
    }
    return k;
}

// A near pair's kernel is looked up by its offset's magnitudes and its
// extinction, rounded to 1 part in 1000 (what the kernel computed for).
struct NearKey {
    Cell d;
    long long sigma;  // round(1000 log sigma), or a floor for sigma 0
    auto operator<=>(const NearKey&) const = default;
};
constexpr long long kNoExtinction = -1000000000LL;

NearKey keyOf(const Cell& d, double sigma) {
    return {{std::abs(d[0]), std::abs(d[1]), std::abs(d[2])},
            sigma > 1e-300 ? (long long)std::llround(1000.0 * std::log(sigma)) : kNoExtinction};
}
double sigmaOf(const NearKey& key) { return key.sigma == kNoExtinction ? 0.0 : std::exp(key.sigma / 1000.0); }

}  // namespace

double uncollidedFluxWork(const DomGrid& grid, size_t sourceCells) {
    return double(grid.count()) * double(sourceCells) * 0.5 * (grid.dims[0] + grid.dims[1] + grid.dims[2]);
}

std::vector<glm::vec4> uncollidedFlux(const DomGrid& grid, const std::vector<double>& source, int bands) {
    Gather g{grid, bands, bands * bands, {}, {}};
    const double longest = std::max({grid.edges.x, grid.edges.y, grid.edges.z});
    for (int a = 0; a < 3; ++a) g.near[a] = int(std::ceil(kNearCells * longest / grid.edges[a]));
    {
        const Vec3 w = glm::normalize(Vec3(0.3141, 0.5772, 0.7548));  // no harmonic vanishes here
        std::vector<double> y(g.moments), yr(g.moments);
        evaluateSh(bands, w, y);
        for (int mask = 0; mask < 8; ++mask) {
            const Vec3 r(mask & 1 ? -w.x : w.x, mask & 2 ? -w.y : w.y, mask & 4 ? -w.z : w.z);
            evaluateSh(bands, r, yr);
            g.sign[mask].resize(g.moments);
            for (int m = 0; m < g.moments; ++m) g.sign[mask][m] = yr[m] / y[m] > 0.0 ? 1.0 : -1.0;
        }
    }
    std::vector<SourceCell> sources;
    const double volume = grid.edges.x * grid.edges.y * grid.edges.z;
    for (int k = 0; k < grid.dims[2]; ++k)
        for (int j = 0; j < grid.dims[1]; ++j)
            for (int i = 0; i < grid.dims[0]; ++i) {
                const Cell c{i, j, k};
                if (source[g.index(c)] > 0.0) sources.push_back({c, source[g.index(c)] * volume});
            }

    // A near pair's extinction, per channel: the cell's own, or the mean along
    // the centres' segment.
    auto nearSigma = [&](const Cell& from, const Cell& to) {
        if (from == to) return g.extinction(from);
        const Vec3 span = Vec3(to[0] - from[0], to[1] - from[1], to[2] - from[2]) * grid.edges;
        return g.opticalDepth(from, to) / glm::length(span);
    };
    auto inside = [&](const Cell& c) {
        return c[0] >= 0 && c[1] >= 0 && c[2] >= 0 && c[0] < grid.dims[0] && c[1] < grid.dims[1] && c[2] < grid.dims[2];
    };
    // The near kernels this problem needs, each computed once.
    std::set<NearKey> needed;
    for (const SourceCell& s : sources)
        for (int dz = -g.near[2]; dz <= g.near[2]; ++dz)
            for (int dy = -g.near[1]; dy <= g.near[1]; ++dy)
                for (int dx = -g.near[0]; dx <= g.near[0]; ++dx) {
                    const Cell t{s.at[0] + dx, s.at[1] + dy, s.at[2] + dz};
                    if (!inside(t)) continue;
                    const glm::dvec3 sigma = nearSigma(s.at, t);
                    for (int c = 0; c < 3; ++c) needed.insert(keyOf({dx, dy, dz}, sigma[c]));
                }
    const std::vector<NearKey> keys(needed.begin(), needed.end());
    std::vector<std::vector<double>> kernels(keys.size());
    tbb::parallel_for(size_t(0), keys.size(),
                      [&](size_t i) { kernels[i] = nearKernel(keys[i].d, sigmaOf(keys[i]), grid.edges, bands); });
    std::map<NearKey, const std::vector<double>*> kernelOf;
    for (size_t i = 0; i < keys.size(); ++i) kernelOf[keys[i]] = &kernels[i];

    std::vector<glm::vec4> out(grid.count() * g.moments, glm::vec4(0.0f));
    tbb::parallel_for(size_t(0), grid.count(), [&](size_t v) {
        const Cell t = grid.index().cell(v);
        std::vector<glm::dvec3> sum(g.moments, glm::dvec3(0.0));
        std::vector<double> y(g.moments);
        for (const SourceCell& s : sources) {
            const Cell d{t[0] - s.at[0], t[1] - s.at[1], t[2] - s.at[2]};
            if (g.isNear(d)) {
                const glm::dvec3 sigma = nearSigma(s.at, t);
                const int mask = (d[0] < 0 ? 1 : 0) | (d[1] < 0 ? 2 : 0) | (d[2] < 0 ? 4 : 0);
                for (int c = 0; c < 3; ++c) {
                    const std::vector<double>& k = *kernelOf.at(keyOf(d, sigma[c]));
                    for (int m = 0; m < g.moments; ++m) sum[m][c] += s.q / volume * g.sign[mask][m] * k[m];
                }
                continue;
            }
            // Far: the point kernel, q V e^{-tau} / (4 pi r^2) along the direction from the source.
            const Vec3 span = Vec3(d[0], d[1], d[2]) * grid.edges;
            const double r = glm::length(span);
            const Vec3 w = span / r;
            const glm::dvec3 tau = g.opticalDepth(s.at, t);
            glm::dvec3 e = glm::exp(-tau) * (s.q / (4.0 * kPi * r * r));
            // The kernel averaged over the two cells, to second order in the
            // cells' size over r. Along w, a point pair's path is longer by the
            // sum over the axes of the difference of two uniform offsets,
            // triangular, whose e^{-sigma x} averages to (sinh(a) / a)^2 with
            // a = sigma |w_a| h_a / 2 (exact for the exponential). Its variance
            // along w and across: v = sum w_a^2 h_a^2 / 6, u = sum (1 - w_a^2) h_a^2 / 6.
            double along = 0.0, across = 0.0;
            for (int a = 0; a < 3; ++a) {
                along += w[a] * w[a] * grid.edges[a] * grid.edges[a] / 6.0;
                across += (1.0 - w[a] * w[a]) * grid.edges[a] * grid.edges[a] / 6.0;
            }
            for (int c = 0; c < 3; ++c) {
                const double sigma = tau[c] / r;
                for (int a = 0; a < 3; ++a) {
                    const double half = 0.5 * sigma * std::abs(w[a]) * grid.edges[a];
                    if (half > 1e-4) e[c] *= std::pow(std::sinh(half) / half, 2);
                }
                // The rest of e^{-sigma r} / r^2's curvature: along w, f'' / f
                // less sigma^2 is 4 sigma / r + 6 / r^2; across, the path
                // lengthens by rho^2 / (2 r), lowering f by (sigma / (2 r) + 1 / r^2) rho^2.
                e[c] *= 1.0 + (2.0 * sigma / r + 3.0 / (r * r)) * along - (0.5 * sigma / r + 1.0 / (r * r)) * across;
            }
            evaluateSh(bands, w, y);
            // Across, the directions spread by an angle of mean square u / r^2,
            // which shrinks band l by l (l + 1) / 4 of it (the sphere's Laplacian).
            for (int l = 1, m = 1; l < bands; ++l)
                for (int k = 0; k < 2 * l + 1; ++k, ++m) y[m] *= 1.0 - l * (l + 1) * across / (4.0 * r * r);
            for (int m = 0; m < g.moments; ++m) sum[m] += e * y[m];
        }
        for (int m = 0; m < g.moments; ++m) out[v * g.moments + m] = glm::vec4(glm::vec3(sum[m]), 0.0f);
    });
    return out;
}

}  // namespace lucent::hybrid
