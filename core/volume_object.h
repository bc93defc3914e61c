#pragma once
// A translucent object ready for light transport queries: its boundary mesh and
// ray caster, its density field and its opaque blockers. Optical depth is
// sigma_t times the density path integral computed here, so one ray serves all
// three colour channels. Every query is in world space: the object stands where
// its transform puts it. Preprocessing and the runtime's samples live in the
// object's own space (objectMesh(), placement()), so one sample file serves
// every placement.
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "core/density_field.h"
#include "core/lazy.h"
#include "core/mesh_raycaster.h"
#include "core/scene.h"
#include "core/triangle_mesh.h"

namespace lucent {

class VolumeObject {
public:
    // Loads and validates the mesh, blockers and density of desc, placed by desc.transform.
    VolumeObject(const ObjectDesc& desc, std::vector<std::string>& warnings);
    // The same from meshes already in memory (closedMesh, core/triangle_mesh.h):
    // desc.mesh and desc.medium.blockers only name them in errors.
    VolumeObject(const ObjectDesc& desc, TriangleMesh mesh, std::vector<TriangleMesh> blockers);

    const ObjectDesc& desc() const { return desc_; }
    // A new refractive index for the medium, in [1, 4] (Error otherwise): the
    // boundary's optics change, nothing of the geometry does (the viewer's ior).
    void setIor(double ior);
    // A new albedo (each channel in [0, 1]) and g (in [-0.999, 0.999]; Error otherwise): what the
    // medium scatters and where, not its extinction (the viewer's albedo and g).
    void setAlbedoAndG(const Rgb& albedo, double g);
    const TriangleMesh& mesh() const { return mesh_; }  // in the world
    // Object to world, and the mesh and blockers as their files give them.
    const Similarity& placement() const { return desc_.transform; }
    bool placed() const { return !desc_.transform.isIdentity(); }
    const TriangleMesh& objectMesh() const { return placed() ? objectMesh_ : mesh_; }
    const std::vector<TriangleMesh>& objectBlockerMeshes() const {
        return placed() ? objectBlockerMeshes_ : blockerMeshes_;
    }
    // Built on first use (a BVH over every face), from any thread.
    const MeshRaycaster& boundary() const {
        return boundary_.get([this] { return MeshRaycaster(mesh_); });
    }
    const DensityField& density() const { return *density_; }

    // Integral of density over the parts of origin + t dir (0 <= t <= tMax, dir unit)
    // inside the object; infinity when a blocker lies in the way. With
    // tMax = infinity this is the path to the boundary through every crossing.
    double densityPath(const Vec3& origin, const Vec3& dir, double tMax = kInfinity) const;
    // The same path with the blockers filled by the medium around them: what the
    // Lucent scheme projects, leaving the blockers' hard shadows to the runtime.
    double densityPathThroughBlockers(const Vec3& origin, const Vec3& dir, double tMax = kInfinity) const;
    // Either path (throughBlockers picks) for up to MeshRaycaster::kPacket rays,
    // traced as one packet: rays side by side cost a fraction of their cost one
    // by one (MeshRaycaster::insideIntervals). Ray k ends at tMax[k], or at the
    // boundary when tMax is empty.
    void densityPaths(std::span<const Vec3> origins, std::span<const Vec3> dirs, bool throughBlockers,
                      std::span<double> out, std::span<const double> tMax = {}) const;

    bool contains(const Vec3& p) const { return boundary().contains(p); }
    // The shading normal at p on the boundary's face: the runtime's, interpolated
    // from the corners (core/triangle_mesh.h).
    Vec3 shadingNormal(uint32_t face, const Vec3& p) const {
        return interpolatedNormal(mesh_, cornerNormals_.get([this] { return cornerNormals(mesh_); })[face], face, p);
    }
    const std::vector<TriangleMesh>& blockerMeshes() const { return blockerMeshes_; }
    bool insideBlocker(const Vec3& p) const;
    // The nearest point of the region p lies in: the boundary, a blocker's surface
    // or, where the density jumps between slabs, the slab's planes.
    Vec3 closestRegionBoundary(const Vec3& p) const { return closestRegionBoundary(p, boundary().closestPoint(p)); }
    // The same when the boundary's nearest point to p is known.
    Vec3 closestRegionBoundary(const Vec3& p, const Vec3& nearestOnBoundary) const;
    // Distance to the first blocker surface along the ray, or infinity.
    double firstBlockerHit(const Vec3& origin, const Vec3& dir) const;

    // sigma_t * density and albedo * that at p (zero inside blockers).
    Rgb extinction(const Vec3& p) const;
    Rgb scattering(const Vec3& p) const { return desc_.medium.albedo * extinction(p); }

private:
    ObjectDesc desc_;
    TriangleMesh objectMesh_;  // only when placed
    TriangleMesh mesh_;
    Lazy<MeshRaycaster> boundary_;
    Lazy<std::vector<std::array<Vec3, 3>>> cornerNormals_;
    std::unique_ptr<DensityField> density_;
    std::vector<MeshRaycaster> blockers_;
    std::vector<TriangleMesh> blockerMeshes_;
    std::vector<TriangleMesh> objectBlockerMeshes_;  // only when placed
};

// exp(-sigma_t * path) per channel, exactly 0 through a blocker (path = infinity)
// even where sigma_t is 0 (0 * infinity must not become NaN).
inline Rgb transmittance(const Rgb& sigmaT, double path) {
    if (path == kInfinity) return Rgb(0.0);
    return glm::exp(-sigmaT * path);
}

// The object's boundary mesh in its own space, from its mesh file (a glTF node's, or
// OBJ, PLY, OFF, STL), checked as loadClosedMesh checks it.
TriangleMesh loadObjectMesh(const ObjectDesc& desc, std::vector<std::string>& warnings);

// Loads every object of scene. Where checkedMeshes[i] holds faces, object i takes
// that mesh (in its own space, already checked: from its sample file, whose
// fingerprint matched) instead of reading its mesh file; its blockers and density
// are read as always.
std::vector<VolumeObject> loadObjects(const SceneDesc& scene, std::vector<std::string>& warnings,
                                      std::vector<TriangleMesh> checkedMeshes = {});

// An object a host holds in memory, no files (a library's way in: preprocessObject
// then makes its samples, translucentObjectFor hands both to the runtime). Its
// fingerprint covers the meshes and the medium, so sample sets made from other
// data are refused. A grid density still names its file.
VolumeObject memoryObject(const std::string& name, TriangleMesh mesh, const MediumDesc& medium,
                          std::vector<TriangleMesh> blockers = {}, const Similarity& transform = {});

}  // namespace lucent
