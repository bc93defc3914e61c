#pragma once
// Ray queries against a closed mesh (Embree for rays, CGAL's AABB tree for distances): every boundary
// crossing along a ray (concave meshes are crossed several times), the parts of a
// ray that lie inside, point containment and distance to the surface.
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "core/math.h"
#include "core/triangle_mesh.h"

namespace lucent {

struct Crossing {
    double t;    // distance along the (unit) ray direction
    bool exits;  // true when the ray leaves the enclosed volume here
    uint32_t face;
};

struct Interval {
    double t0, t1;
};

class MeshRaycaster {
public:
    explicit MeshRaycaster(const TriangleMesh& mesh);
    ~MeshRaycaster();
    MeshRaycaster(MeshRaycaster&&) noexcept;
    MeshRaycaster& operator=(MeshRaycaster&&) noexcept;

    // All crossings with t > 0, sorted, coincident hits on shared edges merged.
    void crossings(const Vec3& origin, const Vec3& dir, std::vector<Crossing>& out) const;

    // The parts of origin + t dir, 0 <= t <= tMax, inside the mesh, sorted.
    // Returns false only when the ray is never inside. originInside says whether
    // the origin lies inside; without it, a first crossing that exits says so.
    bool insideIntervals(const Vec3& origin, const Vec3& dir, double tMax, std::vector<Interval>& out,
                         std::optional<bool> originInside = std::nullopt) const;

    // The same for up to kPacket rays at once, out[k] for ray k up to tMax[k]
    // (every span as long as origins). Rays that run side by side (parallel or
    // converging, from nearby origins) traverse the tree together as one packet,
    // at a fraction of their cost one by one: the SH projection's rays, one
    // direction from neighbouring samples, and the traced light's.
    static constexpr size_t kPacket = 16;
    void insideIntervals(std::span<const Vec3> origins, std::span<const Vec3> dirs, std::span<const double> tMax,
                         std::span<std::vector<Interval>> out) const;

    // Distance to the first crossing, or infinity.
    double firstHit(const Vec3& origin, const Vec3& dir) const;
    // The first crossing in (tMin, tMax]: one nearest-hit traversal, where crossings()
    // collects every hit along the ray (the path tracers' many short queries: a
    // refracting path's next boundary, a flight's tentative collision); falls back
    // to crossings() when the nearest hit is not beyond tMin in double precision.
    std::optional<Crossing> firstCrossing(const Vec3& origin, const Vec3& dir, double tMin,
                                          double tMax = kInfinity) const;

    bool contains(const Vec3& p) const;
    double distanceToSurface(const Vec3& p) const;
    // The point of the surface nearest p; within, when known, bounds its
    // distance and speeds the search (a wrong bound only costs a second search).
    Vec3 closestPoint(const Vec3& p, double within = kInfinity) const;
    const Bounds3& bounds() const { return bounds_; }

private:
    // The crossings of a ray that hit these faces, sorted and merged (crossings()).
    void toCrossings(const std::vector<uint32_t>& faces, const Vec3& origin, const Vec3& dir,
                     std::vector<Crossing>& out) const;
    // insideIntervals() from the ray's crossings.
    bool intervalsFrom(const std::vector<Crossing>& cs, const Vec3& origin, const Vec3& dir, double tMax,
                       std::vector<Interval>& out, std::optional<bool> originInside) const;
    struct Tree;
    std::unique_ptr<Tree> tree_;
    Bounds3 bounds_;
    Vec3 origin_;
};

}  // namespace lucent
