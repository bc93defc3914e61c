#pragma once
// The optical size an object's samples were made for, against the size it is
// drawn at. psi^(drawn / preprocessed) is exact for the attenuation
// (runtime/internal/sample_light.glsl), but the samples' spacing against the
// mean free path, the depth of their layers and the optically thick decision
// hold for the size preprocessing saw (SampleParameters::placementScale).
#include <string>

#include "core/sample_set.h"

namespace lucent {

// The ratio drawn / preprocessed within which stale samples are never more
// than 1.3 points of relative RMSE worse than fresh ones: measured
// on the sphere and the bunny drawn at 0.05 to 16 times the size their samples
// were made for, and on a thick sphere at 1/8 to 1/2 (docs/runtime.md, "Placement").
inline constexpr double kServedSizeRatio = 4.0;

// drawnScale: the placement's scale times any scale of the medium (the
// viewer's). Empty when the samples serve that size; otherwise one line for
// limitations() and the viewer, naming the ratio.
std::string preprocessedSizeLimitation(const std::string& object, double drawnScale, const SampleParameters& samples);

}  // namespace lucent
