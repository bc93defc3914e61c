#pragma once
// The collided scalar flux of a `lucent transport` problem at points, by
// Monte Carlo particle histories, without the solver's cells or directions:
// the truth of the scattering cases that have no published one (Kobayashi's
// problems 2 and 3). With the uncollided flux of uncollided_quadrature.h it
// gives the total.
//
// By reciprocity: with one speed and isotropic scattering, the flux at x of a
// unit point source at y is the flux at y of one at x, and a mirror keeps it
// so. The flux at a detector is therefore int q(y) phi_x(y) dy, where phi_x
// is the flux of a unit point source at the detector itself: histories start
// there, not in the sources, and every history scores its own detector: one
// deep in a shield is no harder than one beside the sources.
//
// A history flies by delta tracking through the regions (reflective faces
// mirror it; unfolded_problem.h) and carries its weight times the albedo at
// each collision (implicit capture). Its scores, each an expected value:
// - at each collision outside the sources, the sources' uncollided flux there
//   (one direction in the cone that holds them, exact along it);
// - from the start and from each collision, what the next collision scores if
//   it falls among the sources (one direction in their cone, one point along
//   it, that point's uncollided flux by one direction). Scored only where it
//   falls, the few histories in a million that fly straight into the sources
//   would dominate the estimate.
// The first flight scores nothing, so the estimate holds only light that has
// collided. Splitting and Russian roulette keep particles going towards the
// sources: the importance is e^{-tau}, tau the least optical depth to them
// (least_optical_depth.h); in the benchmarks' shields (albedo 0.5) the flux
// falls as e^{-0.96 tau}.
#include <cstdint>
#include <vector>

#include "core/transport_problem.h"

namespace lucent {

struct CollidedEstimate {
    std::vector<double> flux;           // at each point: the flux of light that has collided at least once
    std::vector<double> standardError;  // of each, from the spread of independent batches
    long histories = 0;                 // per point
};

// Isotropic scattering only (every region's g 0); throws std::invalid_argument
// otherwise, or where both faces of an axis are reflective. `histories` per
// point. Deterministic for a seed, whatever the thread count.
CollidedEstimate collidedMonteCarlo(const TransportProblem& problem, const std::vector<Vec3>& points, long histories,
                                    int threads = 2, uint64_t seed = 1);

}  // namespace lucent
