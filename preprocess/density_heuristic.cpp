#include "preprocess/density_heuristic.h"

#include "preprocess/internal/openvdb_plugin.h"

namespace lucent {

HeuristicField::~HeuristicField() = default;

std::unique_ptr<HeuristicField> sampleFirstMoment(const VolumeObject& object, const DistanceField& field,
                                                  const HeuristicSettings& settings) {
    return preprocessOpenVdbPlugin().sampleFirstMoment(object, field, settings);
}

}  // namespace lucent
