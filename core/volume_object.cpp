#include "core/volume_object.h"

#include <algorithm>
#include <array>
#include <cstdio>

#include "core/error.h"
#include "core/fingerprint.h"
#include "core/gltf_scene.h"
#include "core/limits.h"

namespace lucent {
namespace {

std::unique_ptr<DensityField> makeDensity(const DensityDesc& d, const Bounds3& objectBounds) {
    switch (d.type) {
        case DensityDesc::Type::Constant:
            return std::make_unique<ConstantDensity>();
        case DensityDesc::Type::Layers:
            return std::make_unique<LayeredDensity>(d.axis, d.values, objectBounds);
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
            throw Error(file.string(),
                        "the transform moves a vertex beyond the 1e13 coordinates Lucent supports "
                        "(docs/robustness.md)");
    }
    if (!(placed.bounds().diagonal() >= kMinObjectSize))
        throw Error(file.string(),
                    "the transform shrinks the object below the 1e-9 size Lucent supports "
                    "(docs/robustness.md)");
    return placed;
}

}  // namespace

std::vector<TriangleMesh> loadBlockers(const ObjectDesc& desc, std::vector<std::string>& warnings) {
    std::vector<TriangleMesh> blockers;
    for (const auto& file : desc.medium.blockers) blockers.push_back(loadClosedMesh(file, warnings));
    return blockers;
}

TriangleMesh loadObjectMesh(const ObjectDesc& desc, std::vector<std::string>& warnings) {
    return desc.gltfNode >= 0 ? loadGltfMesh(desc.mesh, desc.gltfNode, warnings) : loadClosedMesh(desc.mesh, warnings);
}

VolumeObject::VolumeObject(const ObjectDesc& desc, std::vector<std::string>& warnings)
    : VolumeObject(desc, loadObjectMesh(desc, warnings), loadBlockers(desc, warnings)) {}

VolumeObject::VolumeObject(const ObjectDesc& desc, TriangleMesh mesh, std::vector<TriangleMesh> blockers)
    : desc_(desc),
      objectMesh_(std::move(mesh)),
      mesh_(placed() ? placedMesh(objectMesh_, desc.transform, desc.mesh) : std::move(objectMesh_)) {
    if (!placed()) objectMesh_ = TriangleMesh{};
    // The density is the object's: given in its own space, and carried with it.
    density_ = makeDensity(desc.medium.density, objectMesh().bounds());
    if (placed()) density_ = std::make_unique<PlacedDensity>(std::move(density_), desc.transform);
    // sigma_t times the density is what the sample file and the GPU store, in single precision.
    const double peak =
        std::max({desc.medium.sigmaT.r, desc.medium.sigmaT.g, desc.medium.sigmaT.b}) * density_->maximum();
    if (peak > kMaxMagnitude) {
        char text[64];
        std::snprintf(text, sizeof text, "%.3g", peak);
        throw Error(desc.mesh.string(), std::string("sigma_t times the density reaches ") + text +
                                            ", above the 1e30 Lucent stores (docs/robustness.md)");
    }
    for (size_t k = 0; k < blockers.size(); ++k) {
        TriangleMesh& blocker = blockers[k];
        const std::string file = k < desc.medium.blockers.size() ? desc.medium.blockers[k].string()
                                                                 : desc.name + ": blocker " + std::to_string(k);
        if (placed()) {
            objectBlockerMeshes_.push_back(blocker);
            blocker = placedMesh(blocker, desc.transform, file);
        }
        for (const Vec3& p : blocker.positions)
            if (!contains(p)) throw Error(file, "blocker is not inside its object '" + desc.name + "'");
        blockers_.emplace_back(blocker);
        blockerMeshes_.push_back(std::move(blocker));
    }
}

bool VolumeObject::insideBlocker(const Vec3& p) const {
    for (const auto& b : blockers_)
        if (b.contains(p)) return true;
    return false;
}

Vec3 VolumeObject::closestRegionBoundary(const Vec3& p, const Vec3& nearestOnBoundary) const {
    Vec3 best = nearestOnBoundary;
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
    boundary().insideIntervals(origin, dir, tMax, inside);
    double path = 0.0;
    for (const Interval& s : inside) path += density_->integrate(origin + s.t0 * dir, origin + s.t1 * dir);
    return path;
}

void VolumeObject::densityPaths(std::span<const Vec3> origins, std::span<const Vec3> dirs, bool throughBlockers,
                                std::span<double> out, std::span<const double> tMax) const {
    thread_local std::array<std::vector<Interval>, MeshRaycaster::kPacket> inside;
    std::array<double, MeshRaycaster::kPacket> unbounded;
    if (tMax.empty()) {
        unbounded.fill(kInfinity);
        tMax = std::span(unbounded.data(), std::min(origins.size(), unbounded.size()));
    }
    const size_t count = std::min(origins.size(), inside.size());
    boundary().insideIntervals(origins, dirs, tMax, std::span(inside.data(), origins.size()));
    for (size_t k = 0; k < count; ++k) {
        if (!throughBlockers && !blockers_.empty() && firstBlockerHit(origins[k], dirs[k]) < tMax[k]) {
            out[k] = kInfinity;
            continue;
        }
        double path = 0.0;
        for (const Interval& s : inside[k])
            path += density_->integrate(origins[k] + s.t0 * dirs[k], origins[k] + s.t1 * dirs[k]);
        out[k] = path;
    }
}

void VolumeObject::setIor(double ior) {
    if (!(ior >= 1.0 && ior <= 4.0)) throw Error(desc_.name, "ior must lie in [1, 4]");
    desc_.medium.ior = ior;
}

void VolumeObject::setAlbedoAndG(const Rgb& albedo, double g) {
    for (int c = 0; c < 3; ++c)
        if (!(albedo[c] >= 0.0 && albedo[c] <= 1.0)) throw Error(desc_.name, "albedo must lie in [0, 1]");
    if (!(g >= -0.999 && g <= 0.999)) throw Error(desc_.name, "g must lie in [-0.999, 0.999]");
    desc_.medium.albedo = albedo;
    desc_.medium.g = g;
}

Rgb VolumeObject::extinction(const Vec3& p) const {
    if (!blockers_.empty() && insideBlocker(p)) return Rgb(0.0);
    return desc_.medium.sigmaT * density_->at(p);
}

VolumeObject memoryObject(const std::string& name, TriangleMesh mesh, const MediumDesc& medium,
                          std::vector<TriangleMesh> blockers, const Similarity& transform) {
    auto within = [&](const Rgb& v, double lo, double hi, const char* what) {
        for (int c = 0; c < 3; ++c)
            if (!(v[c] >= lo && v[c] <= hi))
                throw Error(
                    name, std::string(what) + " must lie in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
    };
    within(medium.sigmaT, 0.0, kMaxMagnitude, "sigma_t");
    within(medium.albedo, 0.0, 1.0, "albedo");
    within(Rgb(medium.g), -0.999, 0.999, "g");
    within(Rgb(medium.ior), 1.0, 4.0, "ior");
    for (double v : medium.density.values) within(Rgb(v), 0.0, kMaxMagnitude, "a density value");
    ObjectDesc desc;
    desc.name = name;
    desc.mesh = name;
    desc.medium = medium;
    desc.medium.blockers.clear();
    desc.transform = transform;
    Fingerprint fp;
    auto addMesh = [&](const TriangleMesh& m) {
        fp.addBytes(m.positions.data(), m.positions.size() * sizeof(Vec3));
        fp.addBytes(m.triangles.data(), m.triangles.size() * sizeof(m.triangles[0]));
    };
    addMesh(mesh);
    for (const TriangleMesh& b : blockers) addMesh(b);
    const DensityDesc& d = medium.density;
    // Not the albedo, g or ior: the samples do not depend on them (as parseScene's fingerprint).
    fp.addBytes(&medium.sigmaT, sizeof medium.sigmaT);
    fp.addBytes(&d.type, sizeof d.type);
    fp.addBytes(&d.axis, sizeof d.axis);
    fp.addBytes(d.values.data(), d.values.size() * sizeof(double));
    if (d.type == DensityDesc::Type::Grid) {
        fp.addFile(d.file);
        fp.addText(d.gridName);
        fp.addBytes(d.dims, sizeof d.dims);
        fp.addBytes(&d.bounds, sizeof d.bounds);
    }
    desc.fingerprint = fp.value();
    return VolumeObject(desc, std::move(mesh), std::move(blockers));
}

std::vector<VolumeObject> loadObjects(const SceneDesc& scene, std::vector<std::string>& warnings,
                                      std::vector<TriangleMesh> checkedMeshes) {
    warnings.insert(warnings.end(), scene.warnings.begin(), scene.warnings.end());
    std::vector<VolumeObject> objects;
    objects.reserve(scene.objects.size());
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        try {
            const ObjectDesc& desc = scene.objects[i];
            if (i < checkedMeshes.size() && !checkedMeshes[i].triangles.empty())
                objects.emplace_back(desc, std::move(checkedMeshes[i]), loadBlockers(desc, warnings));
            else
                objects.emplace_back(desc, warnings);
        } catch (const Error& e) {
            // Name the scene entry as well as the file that failed.
            throw Error(scene.file.string(), "/objects/" + std::to_string(i) + ": " + e.what());
        }
    }
    return objects;
}

}  // namespace lucent
