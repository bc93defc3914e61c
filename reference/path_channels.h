#pragma once
// How the path tracer's files read one colour channel of a weight: channel < 0
// traces all three at once (grey media), else that channel alone.
#include "core/math.h"

namespace lucent {

inline double channelOf(const Rgb& c, int channel) { return channel < 0 ? c.r : c[channel]; }

// Keeps only the traced channel of an RGB weight.
inline Rgb masked(const Rgb& c, int channel) {
    if (channel < 0) return c;
    Rgb m(0.0);
    m[channel] = c[channel];
    return m;
}

}  // namespace lucent
