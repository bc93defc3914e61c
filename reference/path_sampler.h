#pragma once
// The random numbers of one pixel's paths. Most come from the pixel's own
// stream (core/rng.h). The first tentative collision of each of a path's first
// kStratifiedFlights free flights is drawn instead from a stratified set over
// the pixel's paths: dimension 0 of Sobol's sequence (the van der Corput
// radical inverse of the path's index), each flight with its own nested
// uniform (Owen) scramble and its own shuffle of the paths (Burley,
// "Practical Hash-based Owen Scrambling", JCGT 9(4), 2020). Every path's
// numbers stay uniform and independent across flights, so the estimate is
// unbiased; any power-of-two count of a pixel's first paths is stratified in
// each of those flights, so a pixel that stops early (--noise) keeps most of
// the gain.
//
// Why the flights and not the directions: on the index-matched wax bunny
// (sigma_t 8, albedo 0.95) stratifying the first flight took the variance per
// pixel to 0.75x, the first three to 0.63x, more flights or the first
// scattering direction nothing more (docs/accuracy.md, Full transport).
#include <array>
#include <cstdint>

#include "core/rng.h"

namespace lucent {

class PathSampler {
public:
    static constexpr int kStratifiedFlights = 8;

    // Plain random numbers from rng, no stratification (single walks, tests).
    explicit PathSampler(const Rng& rng) : rng_(rng) {}
    // A pixel's paths, stratified: its stream, from (seed, pixel).
    PathSampler(uint64_t seed, uint64_t pixel);

    // The next path of the pixel; its flights take their place in the strata.
    void startPath(uint32_t index) {
        path_ = index;
        flights_ = 0;
    }
    // Uniform in [0, 1).
    double uniform() { return rng_.uniform(); }
    // Uniform in [0, 1): the first draw of the path's next free flight.
    double flightUniform();

private:
    Rng rng_;
    bool stratified_ = false;
    uint32_t path_ = 0;
    int flights_ = 0;
    std::array<uint32_t, kStratifiedFlights> shuffle_{}, scramble_{};
};

}  // namespace lucent
