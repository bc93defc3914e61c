// The entry point of the plug-in liblucent_preprocess_openvdb
// (preprocess/internal/openvdb_plugin.h).
#include "preprocess/internal/openvdb_plugin.h"
#include "preprocess/openvdb/vdb_density_heuristic.h"
#include "preprocess/openvdb/vdb_distance_field.h"

namespace lucent {
namespace {

std::unique_ptr<DistanceField> createVdbDistanceField(const TriangleMesh& boundary, double voxelSize, double deepest) {
    return std::make_unique<VdbDistanceField>(boundary, voxelSize, deepest);
}

const PreprocessOpenVdbPlugin kTable{createVdbDistanceField, sampleVdbFirstMoment};

}  // namespace
}  // namespace lucent

extern "C" const void* lucentPreprocessOpenVdbPlugin() { return &lucent::kTable; }
