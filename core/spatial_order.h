#pragma once
// An order of points in which neighbours in the order are neighbours in space,
// so that work on consecutive points (rays traced as one packet) stays coherent.
#include <cstdint>
#include <span>
#include <vector>

#include "core/math.h"

namespace lucent {

// The indices of positions in Morton order of a 2^10 grid over their box.
std::vector<uint32_t> spatialOrder(std::span<const Vec3> positions);

}  // namespace lucent
