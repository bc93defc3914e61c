#include "core/mesh_raycaster.h"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <embree3/rtcore.h>

#include <algorithm>
#include <mutex>

#include "core/error.h"

namespace lucent {

// Rays go through Embree: it traverses about 20 times faster than CGAL's AABB
// tree on these meshes (docs/preprocess.md), and rays are the preprocessor's whole
// cost. Distances, needed rarely, go through CGAL's AABB tree, built on first use.
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using CgalTriangle = Kernel::Triangle_3;
using CgalIterator = std::vector<CgalTriangle>::const_iterator;
using Primitive = CGAL::AABB_triangle_primitive<Kernel, CgalIterator>;
using AabbTree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

namespace {

Kernel::Point_3 toCgal(const Vec3& p) { return {p.x, p.y, p.z}; }

RTCDevice sharedDevice() {
    static RTCDevice device = [] {
        RTCDevice d = rtcNewDevice(nullptr);
        if (!d) throw Error("cannot create an Embree device");
        return d;
    }();
    return device;
}

// Collects every hit along the ray and rejects each, so traversal goes on to the end.
struct CollectingContext {
    RTCIntersectContext context;
    std::vector<uint32_t>* faces;
};

void collectHit(const RTCFilterFunctionNArguments* args) {
    auto* collecting = reinterpret_cast<CollectingContext*>(args->context);
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] == 0) continue;
        collecting->faces->push_back(RTCHitN_primID(args->hit, args->N, i));
        args->valid[i] = 0;
    }
}

// An Embree ray from origin (relative to the box centre Embree's vertices are
// given in) along dir, from tnear on.
RTCRayHit rayQuery(const Vec3& origin, const Vec3& dir, double tnear) {
    RTCRayHit query{};
    query.ray.org_x = float(origin.x);
    query.ray.org_y = float(origin.y);
    query.ray.org_z = float(origin.z);
    query.ray.dir_x = float(dir.x);
    query.ray.dir_y = float(dir.y);
    query.ray.dir_z = float(dir.z);
    query.ray.tnear = float(tnear);
    query.ray.tfar = HUGE_VALF;
    query.ray.mask = ~0u;
    query.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    return query;
}

}  // namespace

struct MeshRaycaster::Tree {
    RTCScene scene = nullptr;
    std::vector<Vec3> v0, normal;  // per triangle, for the hit distance in double precision
    double mergeTolerance = 0.0;
    // The mesh, for the distance tree: its triangles in CGAL's form (72 bytes
    // each, five times the mesh) are made when the tree is, since a renderer that
    // only casts rays never asks for it (a third of the first caster's build).
    std::vector<Vec3> positions;
    std::vector<std::array<uint32_t, 3>> indices;
    std::vector<CgalTriangle> triangles;
    AabbTree distanceTree;
    std::once_flag distanceTreeBuilt;
    ~Tree() {
        if (scene) rtcReleaseScene(scene);
    }
};

MeshRaycaster::MeshRaycaster(const TriangleMesh& mesh) : tree_(std::make_unique<Tree>()) {
    bounds_ = mesh.bounds();
    // Embree works in single precision: give it coordinates relative to the box centre.
    origin_ = bounds_.center();
    RTCDevice device = sharedDevice();
    tree_->scene = rtcNewScene(device);
    rtcSetSceneFlags(tree_->scene, RTCSceneFlags(RTC_SCENE_FLAG_ROBUST | RTC_SCENE_FLAG_CONTEXT_FILTER_FUNCTION));
    rtcSetSceneBuildQuality(tree_->scene, RTC_BUILD_QUALITY_HIGH);
    RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                                 3 * sizeof(float), mesh.positions.size()));
    for (size_t i = 0; i < mesh.positions.size(); ++i)
        for (int k = 0; k < 3; ++k) vertices[3 * i + k] = float(mesh.positions[i][k] - origin_[k]);
    auto* indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                                   3 * sizeof(unsigned), mesh.triangles.size()));
    tree_->v0.reserve(mesh.triangles.size());
    tree_->normal.reserve(mesh.triangles.size());
    tree_->positions = mesh.positions;
    tree_->indices = mesh.triangles;
    for (size_t f = 0; f < mesh.triangles.size(); ++f) {
        const auto& t = mesh.triangles[f];
        for (int k = 0; k < 3; ++k) indices[3 * f + k] = t[k];
        tree_->v0.push_back(mesh.positions[t[0]]);
        tree_->normal.push_back(mesh.faceNormal(f));
    }
    rtcCommitGeometry(geometry);
    rtcAttachGeometry(tree_->scene, geometry);
    rtcReleaseGeometry(geometry);
    rtcCommitScene(tree_->scene);
    tree_->mergeTolerance = 1e-9 * std::max(bounds_.diagonal(), 1e-300);
}

MeshRaycaster::~MeshRaycaster() = default;
MeshRaycaster::MeshRaycaster(MeshRaycaster&&) noexcept = default;
MeshRaycaster& MeshRaycaster::operator=(MeshRaycaster&&) noexcept = default;

void MeshRaycaster::crossings(const Vec3& origin, const Vec3& dir, std::vector<Crossing>& out) const {
    out.clear();
    thread_local std::vector<uint32_t> faces;
    faces.clear();
    CollectingContext collecting;
    rtcInitIntersectContext(&collecting.context);
    collecting.context.filter = collectHit;
    collecting.faces = &faces;
    RTCRayHit query = rayQuery(origin - origin_, dir, 0.0);
    rtcIntersect1(tree_->scene, &collecting.context, &query);
    for (uint32_t f : faces) {
        const Vec3& n = tree_->normal[f];
        const double dn = glm::dot(dir, n);
        if (dn == 0.0) continue;  // ray in the triangle's plane: grazing, crosses nothing
        const double t = glm::dot(tree_->v0[f] - origin, n) / dn;
        if (t <= 0.0) continue;
        out.push_back({t, dn > 0.0, f});
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

bool MeshRaycaster::insideIntervals(const Vec3& origin, const Vec3& dir, double tMax, std::vector<Interval>& out,
                                    std::optional<bool> originInside) const {
    out.clear();
    thread_local std::vector<Crossing> cs;
    crossings(origin, dir, cs);
    // Crossings alternate between entries and exits, and the stretch before an exit
    // is inside. A ray that grazes an edge can be reported crossing only one of its
    // two faces (single precision); then two entries or two exits follow each other,
    // and a containment test of the stretch between them settles it.
    bool inside = originInside.value_or(!cs.empty() && cs.front().exits);
    double start = 0.0;
    for (const Crossing& c : cs) {
        if (start >= tMax) break;
        if (c.exits != inside) inside = contains(origin + 0.5 * (start + c.t) * dir);
        if (inside && c.t > start) {
            const double t1 = std::min(c.t, tMax);
            if (!out.empty() && out.back().t1 >= start)
                out.back().t1 = t1;
            else
                out.push_back({start, t1});
        }
        inside = !c.exits;
        start = c.t;
    }
    return !out.empty();
}

double MeshRaycaster::firstHit(const Vec3& origin, const Vec3& dir) const {
    thread_local std::vector<Crossing> cs;
    crossings(origin, dir, cs);
    return cs.empty() ? kInfinity : cs.front().t;
}

std::optional<Crossing> MeshRaycaster::firstCrossing(const Vec3& origin, const Vec3& dir, double tMin) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);  // no filter: Embree keeps the nearest hit
    RTCRayHit query = rayQuery(origin - origin_, dir, tMin);
    rtcIntersect1(tree_->scene, &context, &query);
    if (query.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;
    const uint32_t f = query.hit.primID;
    const Vec3& n = tree_->normal[f];
    const double dn = glm::dot(dir, n);
    const double t = dn != 0.0 ? glm::dot(tree_->v0[f] - origin, n) / dn : 0.0;
    if (!(t > tMin)) {
        // Single precision let through a hit at or before tMin: ask for all of them.
        thread_local std::vector<Crossing> cs;
        crossings(origin, dir, cs);
        for (const Crossing& c : cs)
            if (c.t > tMin) return c;
        return std::nullopt;
    }
    return Crossing{t, dn > 0.0, f};
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

Vec3 MeshRaycaster::closestPoint(const Vec3& p) const {
    std::call_once(tree_->distanceTreeBuilt, [this] {
        const std::vector<Vec3>& v = tree_->positions;
        tree_->triangles.reserve(tree_->indices.size());
        for (const auto& t : tree_->indices)
            tree_->triangles.emplace_back(toCgal(v[t[0]]), toCgal(v[t[1]]), toCgal(v[t[2]]));
        tree_->distanceTree.insert(tree_->triangles.cbegin(), tree_->triangles.cend());
        tree_->distanceTree.build();
        tree_->distanceTree.accelerate_distance_queries();
    });
    const auto q = tree_->distanceTree.closest_point(toCgal(p));
    return Vec3(CGAL::to_double(q.x()), CGAL::to_double(q.y()), CGAL::to_double(q.z()));
}

double MeshRaycaster::distanceToSurface(const Vec3& p) const { return glm::length(closestPoint(p) - p); }

}  // namespace lucent
