#pragma once
// Well-distributed direction sets on the unit sphere, used as equal-weight
// quadratures (weight 4 pi / n each) by the density heuristic and the SH projection.
#include <vector>

#include "core/math.h"
#include "core/rng.h"

namespace lucent {

// The spherical Fibonacci lattice: n points of nearly equal area cells.
std::vector<Vec3> fibonacciSphere(int n);

// A uniformly distributed random rotation; rotating a lattice by it turns the
// quadrature into a randomised (stratified) Monte Carlo estimate without bias.
glm::dmat3 randomRotation(Rng& rng);

}  // namespace lucent
