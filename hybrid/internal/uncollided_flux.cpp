#include "hybrid/internal/uncollided_flux.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <climits>
#include <map>
#include <set>
#include <stdexcept>

#include <tbb/parallel_for.h>

#include "core/spherical_harmonics.h"
#include "hybrid/internal/unfolded_medium.h"

namespace lucent::hybrid {

namespace {

using Cell = std::array<int, 3>;

struct SourceCell {
    Cell at;
    double q;      // source density times the cell's volume: particles per unit time
    double sigma;  // its largest extinction over the channels
};

// A far box is integrated with 3 Gauss points on an axis where it is thicker
// than this optical depth, else 2.
constexpr double kTwoPointDepth = 0.5;
// A far box is split where the mean optical depth of its 2^3 Gauss points'
// paths is further than this from its centre's: a void's mouth seen through a
// wall (Kobayashi's dog-leg at 10/3 cm cells: its worst detector 10.2% from
// the cell's exact average without the split, 7.3% with it; 0.05 is no better
// and doubles problem 1's time).
constexpr double kKinkDepth = 0.2;

// The 2-point Gauss-Legendre rule on [-1/2, 1/2]^3: point i's offset, bit a of
// i choosing its side on axis a (each weighs 1/8).
Vec3 gaussCorner(int i) {
    static const double at = 0.5 / std::sqrt(3.0);
    return Vec3(i & 1 ? at : -at, i & 2 ? at : -at, i & 4 ? at : -at);
}

// The gathering of one problem: the grid, its near range, the harmonics'
// signs and the medium unfolded across the reflective faces.
struct Gather {
    const DomGrid& grid;
    int bands, moments;
    Cell near{};                              // cells per axis within which a pair is near
    std::array<std::vector<double>, 8> sign;  // Y_m of a direction mirrored in the axes of bit mask / Y_m of it

    const UnfoldedMedium& medium;

    glm::dvec3 extinction(const Cell& c) const { return medium.extinction(c); }
    bool isNear(const Cell& d) const {
        return std::abs(d[0]) <= near[0] && std::abs(d[1]) <= near[1] && std::abs(d[2]) <= near[2];
    }
    glm::dvec3 opticalDepth(const Vec3& a, const Vec3& b, bool* uniform = nullptr) const {
        return medium.opticalDepth(a, b, uniform);
    }
    glm::dvec3 opticalDepth(const Cell& a, const Cell& b, bool* uniform = nullptr) const {
        return opticalDepth(centre(a), centre(b), uniform);
    }
    static Vec3 centre(const Cell& c) { return Vec3(c[0] + 0.5, c[1] + 0.5, c[2] + 0.5); }

    // Where the medium between a near pair is not uniform, the uniform
    // kernel at the segment's mean extinction misses how the pairs' paths
    // differ: the pairs near the interface between a source and a void cross
    // less of the source and weigh most (1 / r^2). The ratio of the pairs'
    // e^{-tau} / r^2 summed over 2^3 Gauss points in each cell, through the
    // cells and through the mean, corrects it: the rule's own error cancels in
    // the ratio (a control variate). Per channel.
    glm::dvec3 heterogeneity(const Cell& s, const Cell& t, const glm::dvec3& mean) const {
        glm::dvec3 through(0.0), uniformly(0.0);
        for (int i = 0; i < 8; ++i) {
            const Vec3 y = centre(s) + gaussCorner(i);
            for (int j = 0; j < 8; ++j) {
                const Vec3 x = centre(t) + gaussCorner(j);
                const double r = glm::length((x - y) * grid.edges), w = 1.0 / (r * r);
                through += w * glm::exp(-opticalDepth(y, x));
                uniformly += w * glm::exp(-mean * r);
            }
        }
        return through / uniformly;
    }

    // Adds the far kernel of the box of cells lo to last emitting q in all,
    // alike in every cell, its largest extinction sigma, to target t's
    // moments. Where the medium between is uniform, as one point with its
    // size's second order (addPoint). Else the attenuation across the box
    // need not be smooth, and the box is integrated by Gauss points, each one's
    // light traced through the cells: 2 per axis, 3 on an axis where the box
    // is over kTwoPointDepth thick. That needs the optical depth to vary
    // across the box about linearly: where the mean over its 2^3 Gauss points
    // is more than kKinkDepth off the centre's (light leaving the sources'
    // region by one face or another, or a void's mouth seen through a wall),
    // a box of more than one cell is refused, false, and the caller splits it.
    bool addFar(const Cell& lo, const Cell& last, double q, double sigma, const Cell& t, std::vector<glm::dvec3>& sum,
                std::vector<double>& y) const {
        const Vec3 x = centre(t), mid = 0.5 * (centre(lo) + centre(last));
        const Vec3 size = centre(last) - centre(lo) + Vec3(1.0);
        const glm::dvec3 local = extinction(t);
        bool uniform = true;
        const glm::dvec3 tau = opticalDepth(mid, x, &uniform);
        // A box's light crosses what its centre's does only if its 2^3 Gauss points' does too.
        std::array<Vec3, 8> points;
        std::array<glm::dvec3, 8> taus;
        if (lo != last) {
            glm::dvec3 mean(0.0);
            for (int i = 0; i < 8; ++i) {
                points[i] = mid + size * gaussCorner(i);
                taus[i] = opticalDepth(points[i], x, &uniform);
                mean += taus[i] / 8.0;
            }
            const glm::dvec3 off = glm::abs(mean - tau);
            if (!uniform && std::max({off.x, off.y, off.z}) > kKinkDepth) return false;
        }
        if (uniform) {
            addPoint(mid, size, q, tau, local, x, sum, y);
            return true;
        }
        int order[3];
        for (int a = 0; a < 3; ++a) order[a] = sigma * size[a] * grid.edges[a] > kTwoPointDepth ? 3 : 2;
        if (lo != last && order[0] == 2 && order[1] == 2 && order[2] == 2) {
            // The 2-point rule's points are the ones just traced.
            for (int i = 0; i < 8; ++i) addPoint(points[i], Vec3(0.0), q * 0.125, taus[i], local, x, sum, y);
            return true;
        }
        addGauss(order, mid, size, q, local, x, sum, y);
        return true;
    }

    // The box about mid by Gauss-Legendre's rule of order[a] points on axis a.
    void addGauss(const int order[3], const Vec3& mid, const Vec3& size, double q, const glm::dvec3& local,
                  const Vec3& x, std::vector<glm::dvec3>& sum, std::vector<double>& y) const {
        static const double at2[2] = {-0.5 / std::sqrt(3.0), 0.5 / std::sqrt(3.0)}, w2[2] = {0.5, 0.5};
        static const double at3[3] = {-0.5 * std::sqrt(0.6), 0.0, 0.5 * std::sqrt(0.6)},
                            w3[3] = {5.0 / 18.0, 8.0 / 18.0, 5.0 / 18.0};
        for (int i = 0; i < order[0] * order[1] * order[2]; ++i) {
            const int index[3] = {i % order[0], i / order[0] % order[1], i / (order[0] * order[1])};
            Vec3 offset;
            double weight = 1.0;
            for (int a = 0; a < 3; ++a) {
                offset[a] = order[a] == 2 ? at2[index[a]] : at3[index[a]];
                weight *= order[a] == 2 ? w2[index[a]] : w3[index[a]];
            }
            const Vec3 p = mid + size * offset;
            addPoint(p, Vec3(0.0), q * weight, opticalDepth(p, x), local, x, sum, y);
        }
    }

    // Adds the light of q emitted alike over a box of `size` cells about p
    // (0: a point), through optical depth tau from p to x, to the moments of
    // the cell centred at x of extinction `local`, both averaged to second
    // order in their sizes over r (the box in a medium as uniform as the cell).
    // Along w an offset lengthens the path in its end's medium, e^{-sigma x}
    // averaging to sinh(a) / a per axis and end with a = sigma |w_a| h_a / 2,
    // and e^{-tau} / r^2 curves by 4 sigma / r + 6 / r^2 besides; across, the
    // path lengthens by rho^2 / (2 r), lowering it by (sigma / (2 r) + 1 / r^2)
    // rho^2 with the path's mean sigma, and the directions spread by an angle
    // of mean square rho^2 / r^2, which shrinks band l by l (l + 1) / 4 of it
    // (the sphere's Laplacian). Offsets uniform: variance h_a^2 / 12 per axis and end.
    void addPoint(const Vec3& p, const Vec3& size, double q, const glm::dvec3& tau, const glm::dvec3& local,
                  const Vec3& x, std::vector<glm::dvec3>& sum, std::vector<double>& y) const {
        const Vec3 span = (x - p) * grid.edges;
        const double r = glm::length(span);
        const Vec3 w = span / r;
        glm::dvec3 e = glm::exp(-tau) * (q / (4.0 * kPi * r * r));
        double along = 0.0, across = 0.0;
        for (int a = 0; a < 3; ++a) {
            const double variance = (1.0 + size[a] * size[a]) * grid.edges[a] * grid.edges[a] / 12.0;
            along += w[a] * w[a] * variance;
            across += (1.0 - w[a] * w[a]) * variance;
        }
        for (int c = 0; c < 3; ++c) {
            for (int a = 0; a < 3; ++a)
                for (const double length : {1.0, size[a]}) {
                    const double half = 0.5 * local[c] * std::abs(w[a]) * length * grid.edges[a];
                    if (half > 1e-4) e[c] *= std::sinh(half) / half;
                }
            const double mean = tau[c] / r;
            e[c] *= 1.0 + (2.0 * local[c] / r + 3.0 / (r * r)) * along - (0.5 * mean / r + 1.0 / (r * r)) * across;
        }
        evaluateSh(bands, w, y);
        for (int l = 1, m = 1; l < bands; ++l)
            for (int k = 0; k < 2 * l + 1; ++k, ++m) y[m] *= 1.0 - l * (l + 1) * across / (4.0 * r * r);
        for (int m = 0; m < moments; ++m) sum[m] += e * y[m];
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

// The far field gathers from boxes of source cells: a k-d tree over the
// unfolded source cells, each node a box of cells halved across its longest
// side. A box whose cells all emit alike is seen from afar as one source
// (kFarBoxes of its longest sides away or more), so a distant target traces a
// few boxes instead of every cell.
struct SourceNode {
    Cell lo{}, hi{};       // its cells: lo up to hi, hi excluded
    double q = 0.0;        // particles per unit time, all its cells together
    bool uniform = false;  // every cell a source of the same density
    double sigma = 0.0;    // the largest extinction of its cells
    double depth = 0.0;    // its longest side in optical depth, at that extinction
    int child = -1;        // its first child in the node list, 2 in a row (-1: a leaf)
    int source = -1;       // a leaf's source cell
};
constexpr double kFarBoxes = 3.0;
// A box's attenuation must be smooth enough for its Gauss points: at most
// this optical depth along its longest side (Kobayashi's problem 1 at 10/3 cm
// cells: 1.2% from the exact fluxes; at 2, 2.5%, in half the time).
constexpr double kBoxDepth = 1.0;

// Fills node `index` as the box [lo, hi) over `members` (indices into
// sources, all inside it), and its descendants.
void buildNode(std::vector<SourceNode>& nodes, const std::vector<SourceCell>& sources, size_t index, const Cell& lo,
               const Cell& hi, const Vec3& edges, const std::vector<int>& members) {
    nodes[index].lo = lo;
    nodes[index].hi = hi;
    if (members.empty()) return;
    double q = 0.0, sigma = 0.0;
    bool alike = true;
    for (int m : members) {
        q += sources[m].q;
        sigma = std::max(sigma, sources[m].sigma);
        alike = alike && std::abs(sources[m].q - sources[members.front()].q) <= 1e-12 * sources[members.front()].q;
    }
    nodes[index].q = q;
    nodes[index].sigma = sigma;
    for (int a = 0; a < 3; ++a) nodes[index].depth = std::max(nodes[index].depth, sigma * (hi[a] - lo[a]) * edges[a]);
    const size_t cells = size_t(hi[0] - lo[0]) * size_t(hi[1] - lo[1]) * size_t(hi[2] - lo[2]);
    nodes[index].uniform = alike && members.size() == cells;
    if (cells == 1) {
        nodes[index].source = members.front();
        return;
    }
    int axis = 0;
    for (int a = 1; a < 3; ++a)
        if ((hi[a] - lo[a]) * edges[a] > (hi[axis] - lo[axis]) * edges[axis]) axis = a;
    const int split = lo[axis] + (hi[axis] - lo[axis]) / 2;
    std::vector<int> below, above;
    for (int m : members) (sources[m].at[axis] < split ? below : above).push_back(m);
    const size_t first = nodes.size();
    nodes.resize(first + 2);
    nodes[index].child = int(first);
    Cell belowHi = hi, aboveLo = lo;
    belowHi[axis] = split;
    aboveLo[axis] = split;
    buildNode(nodes, sources, first, lo, belowHi, edges, below);
    buildNode(nodes, sources, first + 1, aboveLo, hi, edges, above);
}

// The k-d tree of the source cells: its root is nodes[0].
std::vector<SourceNode> sourceTree(const std::vector<SourceCell>& sources, const Vec3& edges) {
    Cell lo{INT_MAX, INT_MAX, INT_MAX}, hi{INT_MIN, INT_MIN, INT_MIN};
    for (const SourceCell& s : sources)
        for (int a = 0; a < 3; ++a) {
            lo[a] = std::min(lo[a], s.at[a]);
            hi[a] = std::max(hi[a], s.at[a] + 1);
        }
    std::vector<int> all(sources.size());
    for (size_t i = 0; i < all.size(); ++i) all[i] = int(i);
    std::vector<SourceNode> nodes(1);
    if (!sources.empty()) buildNode(nodes, sources, 0, lo, hi, edges, all);
    return nodes;
}

// Every source cell of the grid (density `source`), and its mirror images.
// A reflective face returns the light that reaches it as if it came from the
// mirror image of its source: each source cell has an image across every
// reflective face and every pair and triple of them (at most 7, for a
// corner), whose light crosses the mirrored medium (UnfoldedMedium).
std::vector<SourceCell> sourceCells(const DomGrid& grid, const std::vector<double>& source,
                                    const std::array<bool, 6>& reflective) {
    std::vector<SourceCell> sources;
    const double volume = grid.edges.x * grid.edges.y * grid.edges.z;
    for (size_t v = 0; v < grid.count(); ++v)
        if (source[v] > 0.0) {
            const glm::vec4 sigma = grid.extinction[v];
            sources.push_back(
                {grid.index().cell(v), source[v] * volume, double(std::max({sigma.r, sigma.g, sigma.b}))});
        }
    for (int a = 0; a < 3; ++a) {
        if (!reflective[2 * a] && !reflective[2 * a + 1]) continue;
        const size_t before = sources.size();
        for (size_t i = 0; i < before; ++i) {
            SourceCell image = sources[i];
            image.at[a] = reflective[2 * a] ? -1 - image.at[a] : 2 * grid.dims[a] - 1 - image.at[a];
            sources.push_back(image);
        }
    }
    return sources;
}

// Walks the tree for target cell t: near(source cell) for each source cell
// within the near range, far(node) for each box or cell seen from afar, which
// returns whether it took the box (else its children are walked).
template <class Near, class Far>
void walk(const std::vector<SourceNode>& tree, const std::vector<SourceCell>& sources, const Gather& g, const Cell& t,
          Near&& near, Far&& far) {
    int stack[128];  // depth first: at most one sibling waits per level, and the tree is under 100 deep
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const SourceNode& n = tree[size_t(stack[--top])];
        if (n.q <= 0.0) continue;
        if (n.child < 0) {
            const SourceCell& s = sources[size_t(n.source)];
            if (g.isNear({t[0] - s.at[0], t[1] - s.at[1], t[2] - s.at[2]}))
                near(s);
            else
                far(n);
            continue;
        }
        // The box's gap to t's centre on the axis where it is widest, and its longest side.
        double gap = -kInfinity, side = 0.0;
        for (int a = 0; a < 3; ++a) {
            const double mid = 0.5 * (n.lo[a] + n.hi[a]), half = 0.5 * (n.hi[a] - n.lo[a]);
            gap = std::max(gap, (std::abs(t[a] + 0.5 - mid) - half) * g.grid.edges[a]);
            side = std::max(side, 2.0 * half * g.grid.edges[a]);
        }
        if (n.uniform && n.depth <= kBoxDepth * (1.0 + 1e-6) && gap >= kFarBoxes * side && far(n)) continue;
        stack[top++] = n.child;
        stack[top++] = n.child + 1;
    }
}

Gather gatherOf(const DomGrid& grid, int bands, const UnfoldedMedium& medium) {
    Gather g{grid, bands, bands * bands, {}, {}, medium};
    const double longest = std::max({grid.edges.x, grid.edges.y, grid.edges.z});
    for (int a = 0; a < 3; ++a) g.near[a] = int(std::ceil(kNearCells * longest / grid.edges[a]));
    const Vec3 w = glm::normalize(Vec3(0.3141, 0.5772, 0.7548));  // no harmonic vanishes here
    std::vector<double> y(g.moments), yr(g.moments);
    evaluateSh(bands, w, y);
    for (int mask = 0; mask < 8; ++mask) {
        const Vec3 r(mask & 1 ? -w.x : w.x, mask & 2 ? -w.y : w.y, mask & 4 ? -w.z : w.z);
        evaluateSh(bands, r, yr);
        g.sign[mask].resize(g.moments);
        for (int m = 0; m < g.moments; ++m) g.sign[mask][m] = yr[m] / y[m] > 0.0 ? 1.0 : -1.0;
    }
    return g;
}

// A near pair's extinction, per channel: the cell's own, or the mean along the
// centres' segment; `uniform` as Gather::opticalDepth.
glm::dvec3 nearSigma(const Gather& g, const Cell& from, const Cell& to, bool* uniform = nullptr) {
    if (from == to) return g.extinction(from);
    const Vec3 span = Vec3(to[0] - from[0], to[1] - from[1], to[2] - from[2]) * g.grid.edges;
    return g.opticalDepth(from, to, uniform) / glm::length(span);
}

// The near kernels a problem needs, each computed once, by key.
std::map<NearKey, std::vector<double>> nearKernels(const Gather& g, const std::vector<SourceCell>& sources) {
    const DomGrid& grid = g.grid;
    auto inside = [&](const Cell& c) {
        return c[0] >= 0 && c[1] >= 0 && c[2] >= 0 && c[0] < grid.dims[0] && c[1] < grid.dims[1] && c[2] < grid.dims[2];
    };
    std::set<NearKey> needed;
    for (const SourceCell& s : sources)
        for (int dz = -g.near[2]; dz <= g.near[2]; ++dz)
            for (int dy = -g.near[1]; dy <= g.near[1]; ++dy)
                for (int dx = -g.near[0]; dx <= g.near[0]; ++dx) {
                    const Cell t{s.at[0] + dx, s.at[1] + dy, s.at[2] + dz};
                    if (!inside(t)) continue;
                    const glm::dvec3 sigma = nearSigma(g, s.at, t);
                    for (int c = 0; c < 3; ++c) needed.insert(keyOf({dx, dy, dz}, sigma[c]));
                }
    const std::vector<NearKey> keys(needed.begin(), needed.end());
    std::vector<std::vector<double>> kernels(keys.size());
    tbb::parallel_for(size_t(0), keys.size(),
                      [&](size_t i) { kernels[i] = nearKernel(keys[i].d, sigmaOf(keys[i]), grid.edges, g.bands); });
    std::map<NearKey, std::vector<double>> kernelOf;
    for (size_t i = 0; i < keys.size(); ++i) kernelOf[keys[i]] = std::move(kernels[i]);
    return kernelOf;
}

}  // namespace

int mirrorImages(const std::array<bool, 6>& reflective) {
    int images = 1;
    for (int a = 0; a < 3; ++a) {
        if (reflective[2 * a] && reflective[2 * a + 1]) return 0;
        if (reflective[2 * a] || reflective[2 * a + 1]) images *= 2;
    }
    return images;
}

double uncollidedFluxWork(const DomGrid& grid, const std::vector<double>& source,
                          const std::array<bool, 6>& reflective) {
    if (mirrorImages(reflective) == 0) return kInfinity;
    const UnfoldedMedium medium(grid, reflective);
    const Gather g = gatherOf(grid, 1, medium);
    const std::vector<SourceCell> sources = sourceCells(grid, source, reflective);
    const std::vector<SourceNode> tree = sourceTree(sources, grid.edges);
    // The far field's traced points, counted by walking the tree for up to
    // 4096 targets spread over the grid (a walk may visit thousands of nodes)
    // as if every box took 3 Gauss points per axis, each as long as half the
    // grid's summed dimensions (bricks ignored): an upper bound; the near
    // pairs cost a lookup.
    const size_t stride = std::max<size_t>(1, grid.count() / 4096), samples = (grid.count() + stride - 1) / stride;
    std::vector<double> points(samples, 0.0);
    tbb::parallel_for(size_t(0), samples, [&](size_t i) {
        walk(
            tree, sources, g, grid.index().cell(i * stride), [&](const SourceCell&) { points[i] += 1.0; },
            [&](const SourceNode& n) {
                points[i] += n.child < 0 ? 8.0 : 36.0;
                return true;
            });
    });
    double total = 0.0;
    for (double p : points) total += p * double(grid.count()) / double(samples);
    return total * 0.5 * (grid.dims[0] + grid.dims[1] + grid.dims[2]);
}

std::vector<glm::vec4> uncollidedFlux(const DomGrid& grid, const std::vector<double>& source, int bands,
                                      const std::array<bool, 6>& reflective) {
    return uncollidedFlux(grid, source, bands, reflective, {0, 0, 0}, grid.dims);
}

std::vector<glm::vec4> uncollidedFlux(const DomGrid& grid, const std::vector<double>& source, int bands,
                                      const std::array<bool, 6>& reflective, const std::array<int, 3>& lo,
                                      const std::array<int, 3>& hi) {
    if (mirrorImages(reflective) == 0)
        throw std::invalid_argument("uncollidedFlux: both faces of an axis are reflective");
    const UnfoldedMedium medium(grid, reflective);
    const Gather g = gatherOf(grid, bands, medium);
    const std::vector<SourceCell> sources = sourceCells(grid, source, reflective);
    const std::vector<SourceNode> tree = sourceTree(sources, grid.edges);
    const std::map<NearKey, std::vector<double>> kernelOf = nearKernels(g, sources);
    const double volume = grid.edges.x * grid.edges.y * grid.edges.z;

    const GridIndex box{{hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]}};
    std::vector<glm::vec4> out(box.count() * g.moments, glm::vec4(0.0f));
    tbb::parallel_for(size_t(0), box.count(), [&](size_t v) {
        const Cell c = box.cell(v), t{c[0] + lo[0], c[1] + lo[1], c[2] + lo[2]};
        std::vector<glm::dvec3> sum(g.moments, glm::dvec3(0.0));
        std::vector<double> y(g.moments);
        auto near = [&](const SourceCell& s) {
            const Cell d{t[0] - s.at[0], t[1] - s.at[1], t[2] - s.at[2]};
            bool uniform = true;
            const glm::dvec3 sigma = nearSigma(g, s.at, t, &uniform);
            const glm::dvec3 scale = uniform ? glm::dvec3(1.0) : g.heterogeneity(s.at, t, sigma);
            const int mask = (d[0] < 0 ? 1 : 0) | (d[1] < 0 ? 2 : 0) | (d[2] < 0 ? 4 : 0);
            for (int c = 0; c < 3; ++c) {
                const std::vector<double>& k = kernelOf.at(keyOf(d, sigma[c]));
                for (int m = 0; m < g.moments; ++m) sum[m][c] += s.q / volume * scale[c] * g.sign[mask][m] * k[m];
            }
        };
        auto far = [&](const SourceNode& n) {
            return g.addFar(n.lo, {n.hi[0] - 1, n.hi[1] - 1, n.hi[2] - 1}, n.q, n.sigma, t, sum, y);
        };
        walk(tree, sources, g, t, near, far);
        for (int m = 0; m < g.moments; ++m) out[v * g.moments + m] = glm::vec4(glm::vec3(sum[m]), 0.0f);
    });
    return out;
}

}  // namespace lucent::hybrid
