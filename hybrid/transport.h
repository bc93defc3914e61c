#pragma once
// `lucent transport`: the discrete ordinates solver of thesis 5.3 on a problem
// file (core/transport_problem.h) instead of a scene, so that it can be checked
// against the standard transport benchmarks. Runs on OpenCL.
#include <array>
#include <memory>
#include <string>
#include <vector>

#include "core/peers.h"
#include "core/transport_problem.h"

namespace lucent::hybrid {

struct TransportResult {
    std::vector<double> flux;     // scalar flux (radiance integrated over 4 pi) at each point, in order
    std::vector<float> cellFlux;  // the same in every cell, i + nx (j + ny k)
    int iterations = 0;
    bool converged = false;
    double seconds = 0;
    std::string device;
    bool uncollidedMarched = false;  // the sources' uncollided flux integrated cell to cell, not swept
    std::string uncollidedWhy;       // why it was swept when auto could not march it
    int ranks = 1;
    double haloBytesPerIteration = 0;  // sent between the ranks, all of them, per iteration
};

// With peers (the ranks of an MPI job), each rank sweeps its share of the
// cells and trades the radiance crossing its faces with its neighbours (KBA,
// hybrid/internal/sweep_halo.h); every rank makes one, and rank 0's result
// holds the flux (the others': no flux).
class TransportSolver {
public:
    // Everything before the ranks talk: the device and its memory, the
    // materials, the first-collision source. Throws Error (an Error here is
    // safe to agree on: no rank waits for another yet).
    TransportSolver(const TransportProblem& problem, const Peers* peers = nullptr);
    ~TransportSolver();
    TransportSolver(const TransportSolver&) = delete;
    TransportSolver& operator=(const TransportSolver&) = delete;
    // The sweeps, with the ranks trading faces, and the flux gathered on rank 0.
    TransportResult solve();

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

// TransportSolver(problem, peers).solve().
TransportResult solveTransport(const TransportProblem& problem, const Peers* peers = nullptr);

// What each rank of `ranks` holds and sends for a grid of `cells` (the largest
// share; docs/scaling.md). whole: the uncollided flux is not "swept", so every
// rank also holds the whole grid's materials for the first-collision source.
struct TransportFootprint {
    std::array<int, 2> processGrid{1, 1};
    double deviceBytes = 0;            // the sweeps' buffers
    double hostBytes = 0;              // materials, source and the flux read back
    double haloBytesPerIteration = 0;  // sent between all ranks
    // A sweep crosses px + py - 1 ranks in blocks of z: the last rank starts
    // this many blocks' time after the first, out of this many.
    int pipelineStages = 0, blocks = 1;
};
TransportFootprint transportFootprint(const std::array<int, 3>& cells, int directions, int bands, int ranks,
                                      bool whole);

}  // namespace lucent::hybrid
