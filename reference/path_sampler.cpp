#include "reference/path_sampler.h"

#include <algorithm>

namespace lucent {
namespace {

uint32_t reverseBits(uint32_t x) {
    x = (x << 16) | (x >> 16);
    x = ((x & 0x00ff00ffu) << 8) | ((x & 0xff00ff00u) >> 8);
    x = ((x & 0x0f0f0f0fu) << 4) | ((x & 0xf0f0f0f0u) >> 4);
    x = ((x & 0x33333333u) << 2) | ((x & 0xccccccccu) >> 2);
    return ((x & 0x55555555u) << 1) | ((x & 0xaaaaaaaau) >> 1);
}

// A hash in which each bit depends only on the bits below it (Laine and
// Karras' construction, with Burley's constants): on reversed bits it flips
// each bit by a hash of the bits above it, Owen's nested uniform scramble.
uint32_t lowerBitsHash(uint32_t x, uint32_t seed) {
    x += seed;
    x ^= x * 0x6c50b47cu;
    x ^= x * 0xb82f1e52u;
    x ^= x * 0xc7afe638u;
    x ^= x * 0x8d22f6e6u;
    return x;
}

uint32_t owenScramble(uint32_t x, uint32_t seed) { return reverseBits(lowerBitsHash(reverseBits(x), seed)); }

}  // namespace

PathSampler::PathSampler(uint64_t seed, uint64_t pixel) : rng_(seed, pixel), stratified_(true) {
    jointShuffle_ = uint32_t(rng_.nextU64());
    jointIndex_ = owenScramble(path_, jointShuffle_);
    for (uint32_t& s : jointScramble_) s = uint32_t(rng_.nextU64());
    for (size_t f = 0; f < shuffle_.size(); ++f) {
        const uint64_t bits = rng_.nextU64();
        shuffle_[f] = uint32_t(bits);
        scramble_[f] = uint32_t(bits >> 32);
    }
}

void PathSampler::startPath(uint32_t index) {
    path_ = index;
    flights_ = 0;
    directions_ = 0;
    if (stratified_) jointIndex_ = owenScramble(path_, jointShuffle_);
}

double PathSampler::finest(uint32_t x) {
    // Within the finest stratum (2^-32), uniform: no value repeats between pixels.
    // (Rounding may reach 1 itself: kept below it.)
    return std::min((double(x) + rng_.uniform()) * 0x1.0p-32, 0x1.fffffffffffffp-1);
}

double PathSampler::jointUniform(int d) {
    // The path's point (its place in the shuffle, from startPath), its scrambled coordinate.
    return finest(owenScramble(sobol(d, jointIndex_), jointScramble_[d]));
}

double PathSampler::flightUniform() {
    if (!stratified_ || flights_ >= kStratifiedFlights) return rng_.uniform();
    const int f = flights_++;
    if (f < kJointBounces) return jointUniform(3 * f);
    // The path's place in this flight's shuffle, then its scrambled radical inverse.
    const int k = f - kJointBounces;
    const uint32_t index = owenScramble(path_, shuffle_[k]);
    return finest(owenScramble(reverseBits(index), scramble_[k]));
}

void PathSampler::directionUniforms(double& u, double& v) {
    const int f = flights_ - 1;
    // Only once for a flight: a second direction there takes plain numbers.
    if (!stratified_ || f < directions_ || f >= kJointBounces) {
        u = rng_.uniform();
        v = rng_.uniform();
        return;
    }
    directions_ = f + 1;
    u = jointUniform(3 * f + 1);
    v = jointUniform(3 * f + 2);
}

}  // namespace lucent
