#pragma once
// The angular side of the discrete ordinates method (thesis chapter 5): the
// propagation directions with their quadrature weights, the geometry of a
// characteristic crossing one voxel along each of them (the A_In,Out and
// s_avg factors of thesis 5.3.1), and the delta-M truncation of the
// Henyey-Greenstein phase function to the moments the solver stores.
#include <array>
#include <vector>

#include "core/math.h"

namespace lucent::hybrid {

// N directions, N / 8 per octant, ordered octant by octant: direction
// octant * perOctant + k has the absolute components of direction k of octant 0
// with the signs of the octant's bits (bit 0: x < 0, bit 1: y < 0, bit 2: z < 0),
// so that mirroring a direction in an axis flips one bit of its octant.
struct Ordinates {
    std::vector<Vec3> directions;  // unit
    std::vector<double> weights;   // sum to 4 pi
    int perOctant = 0;
};

// The counts offered: 24, 48 and 80 (level-symmetric LQ4, LQ6, LQ8), 120 and 168
// (Gauss-Legendre in the polar cosine times equal azimuths, 3 x 5 and 3 x 7 per octant).
const std::vector<int>& ordinateCounts();
// Throws Error naming the counts offered when `count` is not one of them.
Ordinates ordinatesFor(int count);

// How a characteristic along a direction with non-negative components crosses
// a voxel of edges h: light entering through the voxel's In face (0: x, 1: y,
// 2: z, the faces the direction enters by) leaves through its Out face. For
// each (In, Out): share[In][Out], the part of face Out's area reached from In
// (thesis A_In,Out / A_Out); tube[In][Out], the flux through that part per unit
// radiance divided by the voxel's volume; length[In][Out], the mean path length
// s_avg. The lengths are scaled so that sum tube * length = 1 exactly: the tubes
// fill the voxel, which makes the solver conserve energy whatever the
// extinction.
struct VoxelCrossing {
    std::array<std::array<double, 3>, 3> share{}, tube{}, length{};
};
VoxelCrossing voxelCrossing(const Vec3& absDirection, const Vec3& voxelEdges);

// The delta-M truncation (Wiscombe 1977) of Henyey-Greenstein with `bands`
// Legendre bands: the forward peak f = g^bands (0 for g <= 0) is taken as
// unscattered, sigma_s* = (1 - f) sigma_s, sigma_t* = sigma_t - f sigma_s, and
// the scaled phase function has Legendre moments g*_l = (g^l - f) / (1 - f).
struct DeltaM {
    double f = 0;
    std::array<double, 8> moments{};  // g*_l for l < bands (g*_0 = 1)
};
DeltaM deltaM(double g, int bands);

}  // namespace lucent::hybrid
