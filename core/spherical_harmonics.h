#pragma once
// Real spherical harmonics, orthonormal on the unit sphere, Condon-Shortley phase
// included (the convention of google/spherical-harmonics and pbrt-v2, see
// tests/data/real_sh_l4.csv). "order" is the number of bands, so order L
// has L*L coefficients; coefficient (l, m) sits at index l*l + l + m.
#include <span>
#include <vector>

#include "core/math.h"

namespace lucent {

inline constexpr int kMaxShOrder = 16;

inline int shCoefficientCount(int order) { return order * order; }
inline int shIndex(int l, int m) { return l * l + l + m; }

// Writes the order*order basis values at the unit direction dir into out.
void evaluateSh(int order, const Vec3& dir, std::span<double> out);

// Reconstructs f(dir) = sum_i coefficients[i] * Y_i(dir).
double reconstructSh(int order, std::span<const double> coefficients, const Vec3& dir);

}  // namespace lucent
