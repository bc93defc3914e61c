#pragma once
// Partition-of-unity weights for the Gaussians. Thesis eq. 3.3 asks for sum_i
// gamma_i(x) = 1 inside the object, which plain Gaussians cannot give (its
// footnote); unnormalised, the sum is off by a constant factor and the image by
// the same. Two things make it hold:
// - Near a boundary the sum falls to about half, as no Gaussians lie beyond it.
//   Each Gaussian gets a mirror image across the nearest boundary of its region
//   (the method of images of kernel density estimation): for a flat boundary and
//   samples spread evenly under it, the sum of Gaussians and images is as even
//   at the boundary as deep inside. The runtime clips both to the region.
// - Galerkin normalisation: asking the integral of k_i (sum_j w_j k_j) over the
//   region to equal that of k_i, k = gamma + its image and w locally constant,
//   gives
//     w_i = int_in k_i / sum_j int_in k_i k_j,
//   the local average of the sum over the region. Near one flat boundary, by the
//   mirror symmetry, that is int gamma_i / sum_j int gamma_i (gamma_j + gamma_j*)
//   over the whole space, in closed form for Gaussians. Where the region is
//   thinner than a few Gaussian widths (a plate, a tube) the far side clips them
//   too: the region is then taken, around each sample, as the slab between its
//   nearest boundary and the boundary straight across, and the products of
//   Gaussians (Gaussians again) are integrated over that slab in closed form.
//   Gaussians of different regions (density slabs) do not overlap at all.
#include <cmath>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace lucent {

struct WeightedSample {
    glm::vec3 position;
    glm::vec3 image;  // mirrored across the nearest boundary of its region
    float width;      // Gaussian standard deviation
    uint32_t region;  // samples of different regions never overlap
    // The region across the sample, along the line from its nearest boundary:
    // infinity where it is far thicker than the Gaussians reach.
    float thickness = HUGE_VALF;
};

// The share of the region's slab model around s that a Gaussian of width sigma
// centred at p holds (1 where the region is thick).
double insideShare(const WeightedSample& s, const glm::vec3& p, double sigma);
// What s's Gaussian and its image hold inside the region, over what the Gaussian
// alone holds in all space: 1 near a single flat boundary (the image gives back
// what the boundary cuts off), less where the far side clips them too.
double heldInside(const WeightedSample& s);

// reachSigmas: neighbours farther than reachSigmas * width are ignored.
std::vector<float> partitionOfUnityWeights(const std::vector<WeightedSample>& samples, double reachSigmas = 4.0);

// The published scheme (thesis 3.3.2): each Gaussian weighted by its share of
// the sampled volume, w_i = (V / N) / int gamma_i with the share proportional to
// the Gaussian's own volume, i.e. one weight V / sum_k int gamma_k for all.
std::vector<float> volumeShareWeights(const std::vector<float>& widths, double sampledVolume);

}  // namespace lucent
