#pragma once
// The least optical depth from a point to the sources of a `lucent transport`
// problem along any path inside its domain: Dijkstra's shortest paths over a
// grid of nodes about 2 cm apart (26 neighbours, each edge's depth the mean of
// its ends' sigma_t times its length), trilinear between the nodes. Where the
// light from the sources bends round a shield through a duct, the straight
// line's depth is far deeper than the depth the light crosses. The Monte
// Carlo truth (collided_monte_carlo.h) plays its splitting game with it; an
// estimate there stays unbiased however rough this map is.
#include <vector>

#include "bench/unfolded_problem.h"

namespace lucent {

class LeastOpticalDepth {
public:
    explicit LeastOpticalDepth(const UnfoldedProblem& u);
    // At a point of the domain (clamped to it).
    double operator()(const Vec3& x) const;

private:
    size_t index(int x, int y, int z) const { return (size_t(z) * n_[1] + y) * n_[0] + x; }
    Vec3 node(size_t i) const;

    Bounds3 box_;
    int n_[3];
    double h_[3];
    std::vector<double> depth_;
};

}  // namespace lucent
