#pragma once
// DistanceField on an OpenVDB narrow-band level set (the plug-in's side).
#include <openvdb/openvdb.h>

#include "preprocess/distance_field.h"

namespace lucent {

class VdbDistanceField final : public DistanceField {
public:
    VdbDistanceField(const TriangleMesh& boundary, double voxelSize, double deepest);
    std::vector<OffsetLayer> offsetLayers(const std::vector<double>& depths) const override;
    const openvdb::FloatGrid& grid() const { return *grid_; }

private:
    openvdb::FloatGrid::Ptr grid_;
};

}  // namespace lucent
