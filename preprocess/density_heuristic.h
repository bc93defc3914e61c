#pragma once
// The sampling-density heuristic of thesis 3.2.3. The first moment of the
// attenuation, T(x) = integral exp(-tau(x,w)) w dw (eq. 3.5), points to where
// light comes from; its divergence is large where that changes fast (near the
// surface, at corners), so rho = |div T| says where samples are needed.
// Points that receive almost no light (integral exp(-tau) dw / 4 pi < epsilon)
// are culled.
#include <cstdint>
#include <vector>

#include "core/math.h"
#include "core/volume_object.h"

namespace lucent {

struct HeuristicSettings {
    int directions = 64;       // d of thesis 3.2.3
    double step = 0.0;         // h of the central differences (scene units)
    double extinction = 1.0;   // scalar sigma_t the heuristic attenuates with
    double cullEpsilon = 1e-3;
    uint64_t seed = 1;
};

struct HeuristicPoint {
    double density = 0.0;      // |div T|
    double receivable = 0.0;   // integral exp(-tau) dw / (4 pi), in [0, 1]
    bool culled = true;
};

// The first-moment field sampled at the six central-difference neighbours of
// each point (the expensive part: d rays each), then reduced to HeuristicPoints.
struct FirstMomentStencils {
    struct Stencil {
        Vec3 moment[6];   // T at x+h ex, x-h ex, x+h ey, ...
        double zeroth[6]; // integral exp(-tau) dw at the same points
        bool blocked = false;
    };
    std::vector<Stencil> stencils;
    uint64_t raysCast = 0;
};

FirstMomentStencils sampleFirstMoments(const VolumeObject& object, const std::vector<Vec3>& points,
                                       const HeuristicSettings& settings);
std::vector<HeuristicPoint> divergenceDensity(const FirstMomentStencils& moments, const HeuristicSettings& settings);

}  // namespace lucent
