#include "core/volume_object.h"

#include <algorithm>
#include <cstdio>

#include "core/error.h"
#include "core/limits.h"

namespace lucent {
namespace {

std::unique_ptr<DensityField> makeDensity(const DensityDesc& d, const Bounds3& objectBounds) {
    switch (d.type) {
        case DensityDesc::Type::Constant: return std::make_unique<ConstantDensity>();
        case DensityDesc::Type::Layers: return std::make_unique<LayeredDensity>(d.axis, d.values, objectBounds);
        case DensityDesc::Type::Grid:
            if (d.file.extension() == ".vdb") return loadVdbGrid(d.file, d.gridName);
            return loadRawGrid(d.file, d.dims[0], d.dims[1], d.dims[2], d.bounds);
    }
    return nullptr;
}

// The mesh as placed in the world, which must stay within the coordinates and
// above the size Lucent computes right (core/limits.h).
TriangleMesh placedMesh(const TriangleMesh& mesh, const Similarity& placement, const std::filesystem::path& file) {
    TriangleMesh placed = mesh;
    for (Vec3& p : placed.positions) {
        p = placement.point(p);
        if (!isFinite(p) || std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)}) > kMaxCoordinate)
            throw Error(file.string(), "the transform moves a vertex beyond the 1e13 coordinates Lucent supports "
                                       "(docs/robustness.md)");
    }
    if (!(placed.bounds().diagonal() >= kMinObjectSize))
        throw Error(file.string(), "the transform shrinks the object below the 1e-9 size Lucent supports "
                                   "(docs/robustness.md)");
    return placed;
}

}  // namespace

VolumeObject::VolumeObject(const ObjectDesc& desc, std::vector<std::string>& warnings)
    : desc_(desc), objectMesh_(loadClosedMesh(desc.mesh, warnings)),
      mesh_(placed() ? placedMesh(objectMesh_, desc.transform, desc.mesh) : std::move(objectMesh_)),
      boundary_(mesh_), cornerNormals_(cornerNormals(mesh_)) {
    if (!placed()) objectMesh_ = TriangleMesh{};
    // The density is the object's: given in its own space, and carried with it.
    density_ = makeDensity(desc.medium.density, objectMesh().bounds());
    if (placed()) density_ = std::make_unique<PlacedDensity>(std::move(density_), desc.transform);
    // sigma_t times the density is what the sample file and the GPU store, in single precision.
    const double peak = std::max({desc.medium.sigmaT.r, desc.medium.sigmaT.g, desc.medium.sigmaT.b}) * density_->maximum();
    if (peak > kMaxMagnitude) {
        char text[64];
        std::snprintf(text, sizeof text, "%.3g", peak);
        throw Error(desc.mesh.string(), std::string("sigma_t times the density reaches ") + text +
                                            ", above the 1e30 Lucent stores (docs/robustness.md)");
    }
    for (const auto& file : desc.medium.blockers) {
        TriangleMesh blocker = loadClosedMesh(file, warnings);
        if (placed()) {
            objectBlockerMeshes_.push_back(blocker);
            blocker = placedMesh(blocker, desc.transform, file);
        }
        for (const Vec3& p : blocker.positions)
            if (!boundary_.contains(p))
                throw Error(file.string(), "blocker is not inside its object '" + desc.name + "'");
        blockers_.emplace_back(blocker);
        blockerMeshes_.push_back(std::move(blocker));
    }
}

bool VolumeObject::insideBlocker(const Vec3& p) const {
    for (const auto& b : blockers_)
        if (b.contains(p)) return true;
    return false;
}

Vec3 VolumeObject::closestRegionBoundary(const Vec3& p) const {
    Vec3 best = boundary_.closestPoint(p);
    double distance = glm::length(best - p);
    auto consider = [&](const Vec3& q) {
        const double d = glm::length(q - p);
        if (d < distance) best = q, distance = d;
    };
    for (const auto& b : blockers_) consider(b.closestPoint(p));
    if (const auto slab = density_->slabAround(p)) {
        for (double plane : {slab->lo, slab->hi}) {
            if (!std::isfinite(plane)) continue;
            Vec3 q = p;
            q[slab->axis] = plane;
            consider(q);
        }
    }
    return best;
}

double VolumeObject::firstBlockerHit(const Vec3& origin, const Vec3& dir) const {
    double t = kInfinity;
    for (const auto& b : blockers_) t = std::min(t, b.firstHit(origin, dir));
    return t;
}

double VolumeObject::densityPath(const Vec3& origin, const Vec3& dir, double tMax) const {
    if (!blockers_.empty() && firstBlockerHit(origin, dir) < tMax) return kInfinity;
    return densityPathThroughBlockers(origin, dir, tMax);
}

double VolumeObject::densityPathThroughBlockers(const Vec3& origin, const Vec3& dir, double tMax) const {
    thread_local std::vector<Interval> inside;
    boundary_.insideIntervals(origin, dir, tMax, inside);
    double path = 0.0;
    for (const Interval& s : inside) path += density_->integrate(origin + s.t0 * dir, origin + s.t1 * dir);
    return path;
}

Rgb VolumeObject::extinction(const Vec3& p) const {
    if (!blockers_.empty() && insideBlocker(p)) return Rgb(0.0);
    return desc_.medium.sigmaT * density_->at(p);
}

std::vector<VolumeObject> loadObjects(const SceneDesc& scene, std::vector<std::string>& warnings) {
    std::vector<VolumeObject> objects;
    objects.reserve(scene.objects.size());
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        try {
            objects.emplace_back(scene.objects[i], warnings);
        } catch (const Error& e) {
            // Name the scene entry as well as the file that failed.
            throw Error(scene.file.string(), "/objects/" + std::to_string(i) + ": " + e.what());
        }
    }
    return objects;
}

}  // namespace lucent
