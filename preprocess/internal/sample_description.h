#pragma once
// The preprocessor's step from Poisson disks to samples (thesis 3.3.2 and
// Lucent's additions, docs/preprocess.md): each disk outside the blockers gets
// its position, radius and Gaussian width (widened in thin parts), its
// scattering and extinction, the region its Gaussian is clipped to with its
// mirror image there, and its boundary ball.
#include <vector>

#include "core/sample_set.h"
#include "core/volume_object.h"
#include "preprocess/poisson_disk.h"
#include "preprocess/preprocessor.h"
#include "preprocess/sample_weights.h"

namespace lucent {

// What describeSamples leaves for the weights and the projection.
struct DescribedSamples {
    std::vector<Vec3> positions;  // in double precision, as the projection casts its rays from them
    std::vector<WeightedSample> weighted;
};

// Fills set's per-sample arrays from index set.positions.size() on; the
// coefficients and the weights are left to the steps after.
DescribedSamples describeSamples(const VolumeObject& object, const std::vector<DiskSample>& disks,
                                 const PreprocessSettings& settings, SampleSet& set);

}  // namespace lucent
