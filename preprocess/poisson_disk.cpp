#include "preprocess/poisson_disk.h"

#include <algorithm>
#include <cmath>

#include "core/rng.h"

namespace lucent {
namespace {

struct Fragment {
    Vec3 p[3];
    double r[3];
    double area() const { return 0.5 * glm::length(glm::cross(p[1] - p[0], p[2] - p[0])); }
    double longestEdge() const {
        return std::max({glm::length(p[1] - p[0]), glm::length(p[2] - p[1]), glm::length(p[0] - p[2])});
    }
};

// Disks binned into cubic cells, a dense grid of linked lists (no hashing, no
// per-cell allocation). anyNear visits every disk that can lie within reach.
// Each list node holds its disk (centre and radius), so that a visit reads one
// place in memory, not a link and then the disk.
class SampleGrid {
public:
    SampleGrid(const Bounds3& bounds, double cell) : origin_(bounds.min), cell_(cell) {
        const Vec3 extent = bounds.extent();
        // Keep the grid under 2^24 cells; wider cells stay correct, only slower.
        while (cellCount(extent) > (size_t(1) << 24)) cell_ *= 1.5;
        dims_ = glm::ivec3(glm::floor(extent / cell_)) + 1;
        head_.assign(size_t(dims_.x) * dims_.y * dims_.z, -1);
    }
    void insert(const Vec3& p, double radius) {
        const size_t c = flat(cellOf(p));
        nodes_.push_back({glm::dvec4(p, radius), head_[c]});
        head_[c] = int32_t(nodes_.size() - 1);
    }
    // Calls predicate(disk) for the disks in the cells within reach of p, the
    // cell of p first (where a conflict or a covering disk is most likely), until it says yes.
    template <class F>
    bool anyNear(const Vec3& p, double reach, const F& predicate) const {
        const glm::ivec3 c = cellOf(p);
        for (int32_t i = head_[flat(c)]; i >= 0; i = nodes_[i].next)
            if (predicate(nodes_[i].disk)) return true;
        const int k = int(std::ceil(reach / cell_));
        const glm::ivec3 lo = glm::max(c - k, glm::ivec3(0)), hi = glm::min(c + k, dims_ - 1);
        for (int z = lo.z; z <= hi.z; ++z)
            for (int y = lo.y; y <= hi.y; ++y)
                for (int x = lo.x; x <= hi.x; ++x) {
                    if (x == c.x && y == c.y && z == c.z) continue;
                    for (int32_t i = head_[flat({x, y, z})]; i >= 0; i = nodes_[i].next)
                        if (predicate(nodes_[i].disk)) return true;
                }
        return false;
    }

private:
    size_t cellCount(const Vec3& extent) const {
        const Vec3 n = glm::floor(extent / cell_) + 1.0;
        return size_t(n.x * n.y * n.z);
    }
    glm::ivec3 cellOf(const Vec3& p) const {
        return glm::clamp(glm::ivec3(glm::floor((p - origin_) / cell_)), glm::ivec3(0), dims_ - 1);
    }
    size_t flat(const glm::ivec3& c) const { return (size_t(c.z) * dims_.y + c.y) * dims_.x + c.x; }
    Vec3 origin_;
    double cell_;
    glm::ivec3 dims_;
    struct Node {
        glm::dvec4 disk;  // centre, radius
        int32_t next;
    };
    std::vector<int32_t> head_;
    std::vector<Node> nodes_;
};

// Radii vary by a factor of four. One grid sized for the largest radius would make
// small disks scan many neighbours; instead samples go to one grid per octave of
// radius, each with cells as wide as its largest radius, and a query reaches into
// each grid only as far as a disk of that octave (or the query's own radius) can.
class MultiscaleGrid {
public:
    MultiscaleGrid(const Bounds3& bounds, double minRadius, double maxRadius) : minRadius_(minRadius) {
        for (double upper = 2.0 * minRadius;; upper *= 2.0) {
            upper = std::min(upper, maxRadius);
            grids_.emplace_back(bounds, upper);
            uppers_.push_back(upper);
            if (upper >= maxRadius) break;
        }
    }
    void insert(const Vec3& p, double radius) { grids_[octave(radius)].insert(p, radius); }
    template <class F>
    bool anyNear(const Vec3& p, double ownReach, const F& predicate) const {
        for (size_t k = 0; k < grids_.size(); ++k)
            if (grids_[k].anyNear(p, std::max(ownReach, uppers_[k]), predicate)) return true;
        return false;
    }

private:
    size_t octave(double radius) const {
        const double k = std::floor(std::log2(std::max(radius / minRadius_, 1.0)));
        return std::min(size_t(std::max(k, 0.0)), grids_.size() - 1);
    }
    double minRadius_;
    std::vector<SampleGrid> grids_;
    std::vector<double> uppers_;
};

// The fragments of one subdivision level. Their areas are kept apart, packed:
// the pick by rejection reads one at random per try, and reading it from the
// fragment (two cache lines, a cross product and a root) was a fifth of the
// Poisson pass in perf.
struct Level {
    std::vector<Fragment> fragments;
    std::vector<double> areas;  // areas[i] = fragments[i].area()
    double totalArea = 0.0;
    double maxArea = 0.0;
    void add(const Fragment& f) {
        const double a = f.area();
        fragments.push_back(f);
        areas.push_back(a);
        totalArea += a;
        maxArea = std::max(maxArea, a);
    }
    // Takes fragment i out (the last one takes its place).
    Fragment take(size_t i) {
        const Fragment f = fragments[i];
        totalArea = std::max(0.0, totalArea - areas[i]);
        fragments[i] = fragments.back();
        fragments.pop_back();
        areas[i] = areas.back();
        areas.pop_back();
        return f;
    }
};

}  // namespace

std::vector<DiskSample> poissonDiskSample(const RadiusSurface& surface, uint64_t seed, double finestEdge,
                                          size_t maxSamples) {
    std::vector<DiskSample> samples;
    if (surface.triangles.empty()) return samples;
    const auto [minIt, maxIt] = std::minmax_element(surface.radius.begin(), surface.radius.end());
    Bounds3 bounds;
    for (const Vec3& p : surface.positions) bounds.extend(p);
    MultiscaleGrid grid(bounds, *minIt, *maxIt);
    Rng rng(seed, 0x9d5c);

    auto conflicts = [&](const Vec3& x, double rx) {
        return grid.anyNear(x, rx, [&](const glm::dvec4& q) {
            const double r = std::max(rx, q.w);
            const Vec3 d = x - Vec3(q);
            return glm::dot(d, d) < r * r;
        });
    };
    // A disk is convex, so it covers a triangle when it holds all three corners.
    auto covered = [&](const Fragment& f) {
        return grid.anyNear(f.p[0], 0.0, [&](const glm::dvec4& q) {
            const double r2 = q.w * q.w;
            for (const Vec3& c : f.p) {
                const Vec3 d = c - Vec3(q);
                if (glm::dot(d, d) >= r2) return false;
            }
            return true;
        });
    };

    std::vector<Level> levels(1);
    for (const auto& t : surface.triangles) {
        Fragment f{{surface.positions[t[0]], surface.positions[t[1]], surface.positions[t[2]]},
                   {surface.radius[t[0]], surface.radius[t[1]], surface.radius[t[2]]}};
        if (f.area() > 0.0) levels[0].add(f);
    }

    while (true) {
        double remaining = 0.0;
        for (auto& level : levels) {
            if (level.fragments.empty()) level.totalArea = level.maxArea = 0.0;  // clear rounding drift
            remaining += level.totalArea;
        }
        if (remaining <= 0.0) break;
        // Level by its share of the active area, then a fragment by rejection on its area.
        double pick = rng.uniform() * remaining;
        size_t li = 0;
        while (li + 1 < levels.size() && (pick >= levels[li].totalArea || levels[li].fragments.empty())) {
            pick -= levels[li].totalArea;
            ++li;
        }
        Level& level = levels[li];
        if (level.fragments.empty()) continue;
        // maxArea only grows as fragments come, so once the large ones are gone
        // the acceptance rate can fall towards zero (on thin tubes it did, and the
        // loop spun for minutes): after a run of rejections it is recomputed from
        // the fragments left, which bounds the expected tries by max / mean area.
        size_t fi;
        for (int tries = 1;; ++tries) {
            fi = size_t(rng.uniform() * double(level.fragments.size()));
            if (rng.uniform() * level.maxArea <= level.areas[fi]) break;
            if (tries % 64 == 0) level.maxArea = *std::max_element(level.areas.begin(), level.areas.end());
        }
        const Fragment f = level.take(fi);

        if (covered(f)) continue;  // a disk placed since this fragment was queued
        // Throw a dart uniformly into the fragment.
        double u = rng.uniform(), v = rng.uniform();
        if (u + v > 1.0) {
            u = 1.0 - u;
            v = 1.0 - v;
        }
        const Vec3 x = f.p[0] + u * (f.p[1] - f.p[0]) + v * (f.p[2] - f.p[0]);
        const double rx = f.r[0] + u * (f.r[1] - f.r[0]) + v * (f.r[2] - f.r[0]);
        // No disk covered f before the dart, so only the dart's own disk can now.
        bool coveredNow = false;
        if (!conflicts(x, rx)) {
            grid.insert(x, rx);
            samples.push_back({x, rx});
            if (samples.size() >= maxSamples) break;
            coveredNow = std::all_of(f.p, f.p + 3, [&](const Vec3& c) { return glm::dot(c - x, c - x) < rx * rx; });
        }
        if (coveredNow || f.longestEdge() < finestEdge) continue;
        // Split into four at the edge midpoints; uncovered children go one level down.
        const Vec3 m01 = 0.5 * (f.p[0] + f.p[1]), m12 = 0.5 * (f.p[1] + f.p[2]), m20 = 0.5 * (f.p[2] + f.p[0]);
        const double r01 = 0.5 * (f.r[0] + f.r[1]), r12 = 0.5 * (f.r[1] + f.r[2]), r20 = 0.5 * (f.r[2] + f.r[0]);
        const Fragment children[4] = {{{f.p[0], m01, m20}, {f.r[0], r01, r20}},
                                      {{m01, f.p[1], m12}, {r01, f.r[1], r12}},
                                      {{m20, m12, f.p[2]}, {r20, r12, f.r[2]}},
                                      {{m01, m12, m20}, {r01, r12, r20}}};
        if (levels.size() == li + 1) levels.emplace_back();
        for (const Fragment& c : children)
            if (!covered(c)) levels[li + 1].add(c);
    }
    return samples;
}

}  // namespace lucent
