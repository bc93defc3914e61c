#pragma once
#include "preprocess/density_heuristic.h"

namespace lucent {

// field: a VdbDistanceField.
std::unique_ptr<HeuristicField> sampleVdbFirstMoment(const VolumeObject& object, const DistanceField& field,
                                                     const HeuristicSettings& settings);

}  // namespace lucent
