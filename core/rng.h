#pragma once
// Counter-based random numbers: every work item derives its own stream from
// (seed, item index), so results never depend on how work is split between threads.
#include <cstdint>

namespace lucent {

inline uint64_t splitMix64(uint64_t x) {
    x += 0x9e3779b97f4a7c15ull;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
    return x ^ (x >> 31);
}

class Rng {
public:
    Rng(uint64_t seed, uint64_t stream) : state_(splitMix64(seed ^ splitMix64(stream + 0x632be59bd9b4e019ull))) {}
    uint64_t nextU64() {
        state_ += 0x9e3779b97f4a7c15ull;
        return splitMix64(state_);
    }
    // Uniform in [0, 1).
    double uniform() { return double(nextU64() >> 11) * 0x1.0p-53; }

private:
    uint64_t state_;
};

}  // namespace lucent
