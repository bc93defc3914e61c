#pragma once
// `lucent transport`: the discrete ordinates solver of thesis 5.3 on a problem
// file (core/transport_problem.h) instead of a scene, so that it can be checked
// against the standard transport benchmarks. Runs on OpenCL.
#include <string>
#include <vector>

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
};

TransportResult solveTransport(const TransportProblem& problem);

}  // namespace lucent::hybrid
