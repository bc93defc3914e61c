#pragma once
// The signed distance to an object's boundary on a narrow-band grid (negative
// inside), reaching from just outside down to a given depth. The offset layers
// are its iso-surfaces and the density heuristic lives on its voxels.
//
// The grid is OpenVDB's, built in the plug-in liblucent_preprocess_openvdb
// (preprocess/openvdb/, core/plugin_library.h): only preprocessing loads it.
#include <memory>
#include <vector>

#include "core/triangle_mesh.h"

namespace lucent {

struct OffsetLayer {
    double depth;  // distance under the boundary
    TriangleMesh surface;
};

class DistanceField {
public:
    static std::unique_ptr<DistanceField> create(const TriangleMesh& boundary, double voxelSize, double deepest);
    virtual ~DistanceField();

    // Offset layers (thesis 3.2.2), extracted by marching cubes; depths ascending.
    // A depth below the object's deepest point yields no layer, so fewer may return.
    virtual std::vector<OffsetLayer> offsetLayers(const std::vector<double>& depths) const = 0;

    // The grid lives in coordinates relative to centre() (single-precision voxels
    // keep their accuracy for models far from the origin) and divided by scale(),
    // the bounding box's diagonal: OpenVDB sees every object at unit size, so the
    // layers do not depend on the scene's unit.
    const Vec3& centre() const { return centre_; }
    double scale() const { return scale_; }
    Vec3 toWorld(const Vec3& gridPoint) const { return centre_ + scale_ * gridPoint; }
    Vec3 toGrid(const Vec3& world) const { return (world - centre_) / scale_; }
    double voxelSize() const { return voxelSize_; }

protected:
    DistanceField(const TriangleMesh& boundary, double voxelSize);

private:
    Vec3 centre_;
    double scale_;
    double voxelSize_;
};

}  // namespace lucent
