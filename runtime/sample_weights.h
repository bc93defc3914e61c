#pragma once
// Partition-of-unity weights for the Gaussians. Thesis eq. 3.3 asks for sum_i
// gamma_i(x) = 1 inside the object, which plain Gaussians cannot give (its
// footnote); unnormalised, the sum is off by a constant factor and the image by
// the same. Galerkin normalisation: asking the integral of gamma_i (sum_k w_k
// gamma_k) to equal that of gamma_i, with w locally constant, gives
//   w_i = int gamma_i / sum_k int gamma_i gamma_k,
// the local average of the Gaussians' sum, in closed form for Gaussians. Only
// the inside counts (the passes clip every Gaussian to the object), so each
// integral is restricted to the half-space under the boundary's tangent plane,
// which multiplies it by Phi(depth / sigma) of the product Gaussian.
#include <vector>

#include "core/sample_set.h"
#include "core/triangle_mesh.h"

namespace lucent {

// cutoffSigmas: neighbours farther than cutoffSigmas * width are ignored.
std::vector<float> partitionOfUnityWeights(const SampleSet& samples, const TriangleMesh& boundary, double cutoffSigmas);

}  // namespace lucent
