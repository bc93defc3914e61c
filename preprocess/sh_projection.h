#pragma once
// Projection of each sample's directional attenuation psi_i(w) = exp(-tau(b_i, w))
// onto real spherical harmonics (thesis 3.3.1), by an equal-weight quadrature over
// a randomly rotated spherical Fibonacci lattice, and the fraction of the squared
// norm of psi_i that the truncated expansion misses (the thesis's error estimate).
#include <cstdint>
#include <vector>

#include "core/math.h"
#include "core/sample_set.h"
#include "core/volume_object.h"

namespace lucent {

struct ProjectionSettings {
    int order = 5;  // bands; order^2 coefficients per channel
    int directions = 256;
    uint64_t seed = 1;
    // Project psi with the blockers filled by the medium (smooth, so few bands
    // hold it) and leave their shadows to the runtime (the Lucent scheme), rather
    // than with their hard shadows in psi (the published scheme).
    bool shadowBlockersAtRuntime = false;
};

struct ProjectionResult {
    int channels = 1;
    std::vector<float> coefficients;     // [sample][channel][order^2]
    std::vector<float> truncationError;  // per sample, worst channel
    std::vector<BoundaryBall> balls;     // per sample, curvature and share fitted
    uint64_t raysCast = 0;
};

// Distance from depth d inside a ball of the given curvature (0: a half-space) to
// its surface along a direction at cosine cos to the outward normal; infinite
// when a half-space is never left.
double ballExitDistance(double cosine, double depth, double curvature);
// exp(-sigma_t s) along w, at the ball's full share.
Rgb ballTransmittance(const Rgb& sigmaT, const BoundaryBall& ball, const Vec3& w);

// channels = 1 projects with sigma_t.r only (grey media); 3 projects each channel.
// With balls (one per position, normal and depth set, SampleSet::boundary), each
// psi_i is projected less a share of its ball's transmittance, the runtime adding
// it back exactly; the share that leaves the least of psi_i outside the SH bands
// is chosen per sample.
ProjectionResult projectAttenuation(const VolumeObject& object, const std::vector<Vec3>& positions,
                                    const std::vector<BoundaryBall>& balls, const ProjectionSettings& settings,
                                    int channels);

}  // namespace lucent
