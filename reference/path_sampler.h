#pragma once
// The random numbers of one pixel's paths. Most come from the pixel's own
// stream (core/rng.h). The first draws of a path's first bounces come instead
// from point sets stratified over the pixel's paths (Burley, "Practical
// Hash-based Owen Scrambling", JCGT 9(4), 2020):
// - bounces 0 to kJointBounces - 1 (the first tentative collision of the
//   flight, then the two uniforms of the scattering direction that ends it)
//   are one point of Sobol's sequence (reference/sobol.h) in 3 kJointBounces
//   dimensions, one shuffle of the paths for the point and a nested uniform
//   (Owen) scramble for each dimension;
// - the first tentative collision of the later flights, up to
//   kStratifiedFlights, is each stratified alone (van der Corput, its own
//   shuffle and scramble).
// Every path's numbers stay uniform and each is used once, so the estimate is
// unbiased; any power-of-two count of a pixel's first paths is a net in each
// set, so a pixel that stops early (--noise) keeps most of the gain.
//
// Why these: on the index-matched wax bunny (sigma_t 8, albedo 0.95) the
// variance per path of --method path against Cycles' (docs/results/peer-full.md
// scene at 256x256) was 1.54 with each flight stratified alone, 1.35 with each
// bounce's (flight, direction) stratified alone in 3-D, 1.16 with two bounces
// as one 6-D point, 1.13 with three, 1.13 with four; the time did not change.
#include <array>
#include <cstdint>

#include "core/rng.h"
#include "reference/sobol.h"

namespace lucent {

class PathSampler {
public:
    static constexpr int kStratifiedFlights = 8;
    static constexpr int kJointBounces = 3;
    static_assert(3 * kJointBounces <= kSobolDimensions && kJointBounces <= kStratifiedFlights);

    // Plain random numbers from rng, no stratification (single walks, tests).
    explicit PathSampler(const Rng& rng) : rng_(rng) {}
    // A pixel's paths, stratified: its stream, from (seed, pixel).
    PathSampler(uint64_t seed, uint64_t pixel);

    // The next path of the pixel; its flights take their place in the strata.
    void startPath(uint32_t index);
    // Uniform in [0, 1).
    double uniform() { return rng_.uniform(); }
    // Uniform in [0, 1): the first draw of the path's next free flight.
    double flightUniform();
    // Two uniforms in [0, 1) for the scattering direction at the collision
    // that ended the path's latest flight.
    void directionUniforms(double& u, double& v);

private:
    Rng rng_;
    bool stratified_ = false;
    uint32_t path_ = 0;
    int flights_ = 0;
    int directions_ = 0;  // flights whose direction was drawn (each dimension is used once)
    uint32_t jointShuffle_ = 0;
    uint32_t jointIndex_ = 0;  // the path's place in the joint points' shuffle
    std::array<uint32_t, 3 * kJointBounces> jointScramble_{};
    std::array<uint32_t, kStratifiedFlights - kJointBounces> shuffle_{}, scramble_{};

    // Dimension d of the path's joint point.
    double jointUniform(int d);
    // A 32-bit fixed-point value made uniform within its finest stratum.
    double finest(uint32_t x);
};

}  // namespace lucent
