#pragma once
// The collided scalar flux of a `lucent transport` problem at points, by
// Monte Carlo particle histories, without the solver's cells or directions:
// the truth of the scattering cases that have no published one (Kobayashi's
// problems 2 and 3). With the uncollided flux of uncollided_quadrature.h it
// gives the total.
//
// Particles start uniformly in the sources, fly by delta tracking through
// the regions (reflective faces mirror them) and collide; each collision's
// scattered light is scored at every point by the next-event (point
// detector) estimator, e^{-tau} / (4 pi r^2) from every mirror image of the
// collision through the unfolded medium (unfolded_problem.h); the particle
// then goes on with its weight times the albedo (implicit capture). Deep in a
// shield few particles would arrive: at every step of the tracking a particle
// splits where its importance, e to half the optical depth to the nearest
// source, has risen, and plays Russian roulette where it has fallen or its
// weight is low. Within r0 of a point the kernel is its mean over the ball of
// radius r0, 3 / (4 pi r0^2): the estimator's variance is finite and its bias
// of order (r0 / the flux's scale)^2.
#include <cstdint>
#include <vector>

#include "core/transport_problem.h"

namespace lucent {

struct CollidedEstimate {
    std::vector<double> flux;           // at each point: the flux of light that has collided at least once
    std::vector<double> standardError;  // of each, from the spread of independent batches
    long histories = 0;
};

// Isotropic scattering only (every region's g 0); throws std::invalid_argument
// otherwise, or where both faces of an axis are reflective. Deterministic for
// a seed and thread count.
CollidedEstimate collidedMonteCarlo(const TransportProblem& problem, const std::vector<Vec3>& points, long histories,
                                    int threads = 2, uint64_t seed = 1, double r0 = 1.0);

}  // namespace lucent
