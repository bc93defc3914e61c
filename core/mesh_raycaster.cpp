#include "core/mesh_raycaster.h"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>

namespace lucent {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using CgalTriangle = Kernel::Triangle_3;
using CgalIterator = std::vector<CgalTriangle>::const_iterator;
using Primitive = CGAL::AABB_triangle_primitive<Kernel, CgalIterator>;
using AabbTree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

struct MeshRaycaster::Tree {
    std::vector<CgalTriangle> triangles;
    std::vector<Vec3> v0, normal;  // per triangle, for the hit distance
    AabbTree tree;
    double mergeTolerance = 0.0;
};

namespace {
Kernel::Point_3 toCgal(const Vec3& p) { return {p.x, p.y, p.z}; }
}  // namespace

MeshRaycaster::MeshRaycaster(const TriangleMesh& mesh) : tree_(std::make_unique<Tree>()) {
    bounds_ = mesh.bounds();
    tree_->triangles.reserve(mesh.triangles.size());
    for (size_t f = 0; f < mesh.triangles.size(); ++f) {
        const auto& t = mesh.triangles[f];
        tree_->triangles.emplace_back(toCgal(mesh.positions[t[0]]), toCgal(mesh.positions[t[1]]),
                                      toCgal(mesh.positions[t[2]]));
        tree_->v0.push_back(mesh.positions[t[0]]);
        tree_->normal.push_back(mesh.faceNormal(f));
    }
    tree_->tree.insert(tree_->triangles.cbegin(), tree_->triangles.cend());
    tree_->tree.build();
    tree_->tree.accelerate_distance_queries();  // built now: queries later are const and thread-safe
    tree_->mergeTolerance = 1e-10 * std::max(bounds_.diagonal(), 1e-300);
}

MeshRaycaster::~MeshRaycaster() = default;
MeshRaycaster::MeshRaycaster(MeshRaycaster&&) noexcept = default;
MeshRaycaster& MeshRaycaster::operator=(MeshRaycaster&&) noexcept = default;

void MeshRaycaster::crossings(const Vec3& origin, const Vec3& dir, std::vector<Crossing>& out) const {
    out.clear();
    thread_local std::vector<AabbTree::Primitive_id> hits;
    hits.clear();
    const Kernel::Ray_3 ray(toCgal(origin), Kernel::Vector_3(dir.x, dir.y, dir.z));
    tree_->tree.all_intersected_primitives(ray, std::back_inserter(hits));
    for (const auto& id : hits) {
        const size_t f = size_t(id - tree_->triangles.cbegin());
        const Vec3& n = tree_->normal[f];
        const double dn = glm::dot(dir, n);
        if (dn == 0.0) continue;  // ray in the triangle's plane: grazing, crosses nothing
        const double t = glm::dot(tree_->v0[f] - origin, n) / dn;
        if (t <= 0.0) continue;
        out.push_back({t, dn > 0.0, uint32_t(f)});
    }
    std::sort(out.begin(), out.end(), [](const Crossing& a, const Crossing& b) { return a.t < b.t; });
    // A ray through a shared edge or vertex hits every face there: keep one crossing
    // per direction of travel.
    size_t kept = 0;
    for (size_t i = 0; i < out.size(); ++i) {
        if (kept > 0 && out[i].t - out[kept - 1].t <= tree_->mergeTolerance && out[i].exits == out[kept - 1].exits)
            continue;
        out[kept++] = out[i];
    }
    out.resize(kept);
}

bool MeshRaycaster::insideIntervals(const Vec3& origin, const Vec3& dir, double tMax,
                                    std::vector<Interval>& out) const {
    out.clear();
    thread_local std::vector<Crossing> cs;
    crossings(origin, dir, cs);
    // The ray is outside after its last crossing, so the stretch before each
    // crossing is inside exactly when that crossing is an exit.
    double start = 0.0;
    for (const Crossing& c : cs) {
        if (start >= tMax) break;
        if (c.exits && c.t > start) {
            const double t1 = std::min(c.t, tMax);
            if (!out.empty() && out.back().t1 >= start) out.back().t1 = t1;
            else out.push_back({start, t1});
        }
        start = c.t;
    }
    return !out.empty();
}

double MeshRaycaster::firstHit(const Vec3& origin, const Vec3& dir) const {
    thread_local std::vector<Crossing> cs;
    crossings(origin, dir, cs);
    return cs.empty() ? kInfinity : cs.front().t;
}

bool MeshRaycaster::contains(const Vec3& p) const {
    if (!bounds_.contains(p)) return false;
    // Majority over three unrelated directions guards against a ray that grazes an edge.
    static const Vec3 dirs[3] = {glm::normalize(Vec3(0.5773, 0.5812, 0.5735)),
                                 glm::normalize(Vec3(-0.3119, 0.8017, -0.5100)),
                                 glm::normalize(Vec3(0.7071, -0.4123, -0.5745))};
    thread_local std::vector<Crossing> cs;
    int votes = 0;
    for (const Vec3& d : dirs) {
        crossings(p, d, cs);
        votes += (!cs.empty() && cs.front().exits) ? 1 : 0;
    }
    return votes >= 2;
}

Vec3 MeshRaycaster::unitNormal(uint32_t face) const { return glm::normalize(tree_->normal[face]); }

double MeshRaycaster::distanceToSurface(const Vec3& p) const {
    return std::sqrt(CGAL::to_double(tree_->tree.squared_distance(toCgal(p))));
}

}  // namespace lucent
