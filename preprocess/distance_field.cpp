#include "preprocess/distance_field.h"

#include <algorithm>

#include "preprocess/internal/openvdb_plugin.h"

namespace lucent {

std::unique_ptr<DistanceField> DistanceField::create(const TriangleMesh& boundary, double voxelSize, double deepest) {
    return preprocessOpenVdbPlugin().createDistanceField(boundary, voxelSize, deepest);
}

// The grid lives in the object's own frame: centred on its bounding box and in
// units of its diagonal. OpenVDB's voxel lattice and its tolerances are then the
// same for the object at any scale and position, so the layers, and the samples
// on them, scale with the scene (OpenVDB also refuses voxels below about 1e-8).
DistanceField::DistanceField(const TriangleMesh& boundary, double voxelSize)
    : centre_(boundary.bounds().center()),
      scale_(std::max(boundary.bounds().diagonal(), 1e-300)),
      voxelSize_(voxelSize) {}

DistanceField::~DistanceField() = default;

}  // namespace lucent
