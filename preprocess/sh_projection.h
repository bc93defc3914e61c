#pragma once
// Projection of each sample's directional attenuation psi_i(w) = exp(-tau(b_i, w))
// onto real spherical harmonics (thesis 3.3.1), by an equal-weight quadrature over
// a randomly rotated spherical Fibonacci lattice, and the fraction of the squared
// norm of psi_i that the truncated expansion misses (the thesis's error estimate).
#include <cstdint>
#include <vector>

#include "core/math.h"
#include "core/volume_object.h"

namespace lucent {

struct ProjectionSettings {
    int order = 5;          // bands; order^2 coefficients per channel
    int directions = 256;
    uint64_t seed = 1;
};

struct ProjectionResult {
    int channels = 1;
    std::vector<float> coefficients;     // [sample][channel][order^2]
    std::vector<float> truncationError;  // per sample, worst channel
    uint64_t raysCast = 0;
};

// channels = 1 projects with sigma_t.r only (grey media); 3 projects each channel.
ProjectionResult projectAttenuation(const VolumeObject& object, const std::vector<Vec3>& positions,
                                    const ProjectionSettings& settings, int channels);

}  // namespace lucent
