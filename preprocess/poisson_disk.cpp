#include "preprocess/poisson_disk.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <unordered_map>

#include <tbb/parallel_for.h>

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

// A placed disk, a node of its grid cell's list. The node holds the disk
// (centre and radius), so that a visit reads one place in memory, not a link and
// then the disk. Nodes live in their tile's arena (a deque: they never move).
struct DiskNode {
    glm::dvec4 disk;  // centre, radius
    const DiskNode* next = nullptr;
};

// Disks binned into cubic cells, a dense grid of linked lists (no hashing, no
// per-cell allocation). anyNear visits every disk that can lie within reach.
// Tiles of one parity class write and read disjoint cells (poissonDiskSample),
// so they share one grid without locks.
class SampleGrid {
public:
    SampleGrid(const Bounds3& bounds, double cell) : origin_(bounds.min), cell_(cell) {
        const Vec3 extent = bounds.extent();
        // Keep the grid under 2^24 cells; wider cells stay correct, only slower.
        while (cellCount(extent) > (size_t(1) << 24)) cell_ *= 1.5;
        dims_ = glm::ivec3(glm::floor(extent / cell_)) + 1;
        head_.assign(size_t(dims_.x) * dims_.y * dims_.z, nullptr);
    }
    void insert(DiskNode& node) {
        const size_t c = flat(cellOf(Vec3(node.disk)));
        node.next = head_[c];
        head_[c] = &node;
    }
    // Calls predicate(disk) for the disks in the cells within reach of p, the
    // cell of p first (where a conflict or a covering disk is most likely), until
    // it says yes. The cells read lie within reach + 2 cell() of p on each axis.
    template <class F>
    bool anyNear(const Vec3& p, double reach, const F& predicate) const {
        const glm::ivec3 c = cellOf(p);
        for (const DiskNode* i = head_[flat(c)]; i; i = i->next)
            if (predicate(i->disk)) return true;
        const int k = int(std::ceil(reach / cell_));
        const glm::ivec3 lo = glm::max(c - k, glm::ivec3(0)), hi = glm::min(c + k, dims_ - 1);
        for (int z = lo.z; z <= hi.z; ++z)
            for (int y = lo.y; y <= hi.y; ++y)
                for (int x = lo.x; x <= hi.x; ++x) {
                    if (x == c.x && y == c.y && z == c.z) continue;
                    for (const DiskNode* i = head_[flat({x, y, z})]; i; i = i->next)
                        if (predicate(i->disk)) return true;
                }
        return false;
    }
    double cell() const { return cell_; }

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
    std::vector<const DiskNode*> head_;
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
    void insert(DiskNode& node) { grids_[octave(node.disk.w)].insert(node); }
    template <class F>
    bool anyNear(const Vec3& p, double ownReach, const F& predicate) const {
        for (size_t k = 0; k < grids_.size(); ++k)
            if (grids_[k].anyNear(p, std::max(ownReach, uppers_[k]), predicate)) return true;
        return false;
    }
    // How far from a point the cells anyNear reads reach, on each axis, for a
    // query whose own reach is at most maxReach.
    double readReach(double maxReach) const {
        double widest = 0.0;
        for (size_t k = 0; k < grids_.size(); ++k)
            widest = std::max(widest, std::max(maxReach, uppers_[k]) + 2.0 * grids_[k].cell());
        return widest;
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

// The four triangles between f's corners and its edge midpoints.
std::array<Fragment, 4> quarters(const Fragment& f) {
    const Vec3 m01 = 0.5 * (f.p[0] + f.p[1]), m12 = 0.5 * (f.p[1] + f.p[2]), m20 = 0.5 * (f.p[2] + f.p[0]);
    const double r01 = 0.5 * (f.r[0] + f.r[1]), r12 = 0.5 * (f.r[1] + f.r[2]), r20 = 0.5 * (f.r[2] + f.r[0]);
    return {Fragment{{f.p[0], m01, m20}, {f.r[0], r01, r20}}, Fragment{{m01, f.p[1], m12}, {r01, f.r[1], r12}},
            Fragment{{m20, m12, f.p[2]}, {r20, r12, f.r[2]}}, Fragment{{m01, m12, m20}, {r01, r12, r20}}};
}

// The part of the surface whose fragments have their centroid in one cube of
// the tile lattice: its fragments by level, its random stream and the disks
// placed in it.
struct Tile {
    uint64_t key = 0;  // index in the lattice: the random stream
    int parity = 0;    // which of the lattice's eight parity classes
    std::vector<Level> levels = std::vector<Level>(1);
    Rng rng{0, 0};
    std::deque<DiskNode> disks;

    // The area its fragments still hold.
    double activeArea() {
        double remaining = 0.0;
        for (auto& level : levels) {
            if (level.fragments.empty()) level.totalArea = level.maxArea = 0.0;  // clear rounding drift
            remaining += level.totalArea;
        }
        return remaining;
    }
};

// Hierarchical dart throwing over one tile's fragments: up to picks fragments
// drawn, fewer when none is left or the tile holds maxSamples disks.
void throwDarts(Tile& tile, MultiscaleGrid& grid, size_t picks, double finestEdge, size_t maxSamples) {
    Rng& rng = tile.rng;
    std::vector<Level>& levels = tile.levels;
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

    for (size_t pick = 0; pick < picks && tile.disks.size() < maxSamples; ++pick) {
        const double remaining = tile.activeArea();
        if (remaining <= 0.0) break;
        // Level by its share of the active area, then a fragment by rejection on its area.
        double at = rng.uniform() * remaining;
        size_t li = 0;
        while (li + 1 < levels.size() && (at >= levels[li].totalArea || levels[li].fragments.empty())) {
            at -= levels[li].totalArea;
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
            tile.disks.push_back({glm::dvec4(x, rx)});
            grid.insert(tile.disks.back());
            coveredNow = std::all_of(f.p, f.p + 3, [&](const Vec3& c) { return glm::dot(c - x, c - x) < rx * rx; });
        }
        if (coveredNow || f.longestEdge() < finestEdge) continue;
        // Uncovered quarters go one level down.
        if (levels.size() == li + 1) levels.emplace_back();
        for (const Fragment& c : quarters(f))
            if (!covered(c)) levels[li + 1].add(c);
    }
}

// The surface's triangles cut into fragments no longer than maxEdge, binned
// into tiles of the given side by their centroid; the tiles in lattice order.
std::vector<Tile> tiledFragments(const RadiusSurface& surface, const Bounds3& bounds, double maxEdge, double side) {
    const glm::ivec3 dims = glm::ivec3(glm::floor(bounds.extent() / side)) + 1;
    std::unordered_map<uint64_t, size_t> slotOf;
    std::vector<Tile> tiles;
    auto place = [&](const Fragment& f) {
        const Vec3 centroid = (f.p[0] + f.p[1] + f.p[2]) / 3.0;
        const glm::ivec3 c =
            glm::clamp(glm::ivec3(glm::floor((centroid - bounds.min) / side)), glm::ivec3(0), dims - 1);
        const uint64_t key = (uint64_t(c.z) * uint64_t(dims.y) + uint64_t(c.y)) * uint64_t(dims.x) + uint64_t(c.x);
        auto [it, fresh] = slotOf.try_emplace(key, tiles.size());
        if (fresh) {
            tiles.emplace_back();
            tiles.back().key = key;
            tiles.back().parity = (c.x & 1) | (c.y & 1) << 1 | (c.z & 1) << 2;
        }
        tiles[it->second].levels[0].add(f);
    };
    std::vector<Fragment> stack;
    for (const auto& t : surface.triangles) {
        stack.push_back({{surface.positions[t[0]], surface.positions[t[1]], surface.positions[t[2]]},
                         {surface.radius[t[0]], surface.radius[t[1]], surface.radius[t[2]]}});
        while (!stack.empty()) {
            const Fragment f = stack.back();
            stack.pop_back();
            if (!(f.area() > 0.0)) continue;
            if (f.longestEdge() <= maxEdge) {
                place(f);
                continue;
            }
            for (const Fragment& q : quarters(f)) stack.push_back(q);
        }
    }
    std::sort(tiles.begin(), tiles.end(), [](const Tile& a, const Tile& b) { return a.key < b.key; });
    return tiles;
}

}  // namespace

// The surface is cut into tiles, cubes of a lattice, and the tiles of each of
// the lattice's eight parity classes take their darts at once, class after
// class (as in Bowers, Wang, Wei and Maletz's parallel sampling of surfaces).
// Every fragment, and every dart thrown into it, lies within e (the longest
// fragment edge, at most the largest radius) of its tile. Two tiles of one class
// are a whole tile apart on some axis, so a side of 2e plus the reach of the
// grid's reads keeps their darts out of conflict and the grid cells one writes
// apart from those the other reads: they share the grid without locks.
//
// A class does not fill its tiles at once: a tile filled before its neighbours
// packs too many disks along its faces and leaves too few beside them (+20% and
// -20% in strips a radius wide on a slab's layers), and a soft shadow falling
// on such a seam came out with 1.5 to 2 times the error
// (SphereLight.SsAndThePathTracerSoftenTheShadowAsTheReferenceDoes). The work
// goes in rounds instead, each of an eighth as many picks as the surface has
// fragments, shared between the tiles by their active area, as one sequential
// pass would draw them: no seam then shows in the density.
//
// Each tile draws from its own random stream, takes a number of picks set
// before its class starts, and the tiles' disks are gathered in lattice order,
// so the samples do not depend on the thread count.
std::vector<DiskSample> poissonDiskSample(const RadiusSurface& surface, uint64_t seed, double finestEdge,
                                          size_t maxSamples) {
    std::vector<DiskSample> samples;
    if (surface.triangles.empty() || maxSamples == 0) return samples;
    const auto [minIt, maxIt] = std::minmax_element(surface.radius.begin(), surface.radius.end());
    const double rMax = *maxIt;
    Bounds3 bounds;
    for (const Vec3& p : surface.positions) bounds.extend(p);
    MultiscaleGrid grid(bounds, *minIt, rMax);
    const double e = std::max(rMax, finestEdge);
    if (!(e > 0.0) || !std::isfinite(e)) return samples;  // no disk to place
    const double side = 1.01 * (2.0 * e + grid.readReach(rMax));
    std::vector<Tile> tiles = tiledFragments(surface, bounds, e, side);

    size_t fragments = 0;
    std::array<std::vector<Tile*>, 8> classes;
    for (Tile& tile : tiles) {
        tile.rng = Rng(seed, (uint64_t(0x9d5c) << 48) + tile.key);
        fragments += tile.levels[0].fragments.size();
        classes[size_t(tile.parity)].push_back(&tile);
    }
    const double picksPerRound = std::max(double(fragments) / 8.0, double(tiles.size()));
    size_t placed = 0;
    while (placed < maxSamples) {
        double active = 0.0;
        for (Tile& tile : tiles) active += tile.activeArea();
        if (!(active > 0.0)) break;
        for (size_t c = 0; c < classes.size() && placed < maxSamples; ++c) {
            const std::vector<Tile*>& batch = classes[c];
            tbb::parallel_for(size_t(0), batch.size(), [&](size_t i) {
                const double area = batch[i]->activeArea();
                if (area > 0.0)
                    throwDarts(*batch[i], grid, size_t(std::ceil(picksPerRound * area / active)), finestEdge,
                               maxSamples);
            });
            placed = 0;
            for (const Tile& tile : tiles) placed += tile.disks.size();
        }
    }
    for (const Tile& tile : tiles)
        for (const DiskNode& d : tile.disks) {
            if (samples.size() >= maxSamples) break;
            samples.push_back({Vec3(d.disk), d.disk.w});
        }
    return samples;
}

}  // namespace lucent
