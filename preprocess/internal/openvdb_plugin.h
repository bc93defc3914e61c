#pragma once
// The functions of the plug-in liblucent_preprocess_openvdb (preprocess/openvdb/,
// core/plugin_library.h), which holds preprocessing's OpenVDB grids.
#include <memory>

#include "preprocess/density_heuristic.h"
#include "preprocess/distance_field.h"

namespace lucent {

struct PreprocessOpenVdbPlugin {
    std::unique_ptr<DistanceField> (*createDistanceField)(const TriangleMesh& boundary, double voxelSize,
                                                          double deepest);
    // field: one that createDistanceField made.
    std::unique_ptr<HeuristicField> (*sampleFirstMoment)(const VolumeObject& object, const DistanceField& field,
                                                         const HeuristicSettings& settings);
};

// Opens the plug-in on first use.
const PreprocessOpenVdbPlugin& preprocessOpenVdbPlugin();

}  // namespace lucent
