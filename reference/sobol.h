#pragma once
// Sobol's sequence in its first kSobolDimensions dimensions, unscrambled, as
// 32-bit fixed point (value / 2^32). Dimension 0 is the van der Corput radical
// inverse; the others come from Joe and Kuo's primitive polynomials and
// initial direction numbers ("Constructing Sobol sequences with better
// two-dimensional projections", SIAM J. Sci. Comput. 30(5), 2008; the file
// new-joe-kuo-6.21201). The path sampler scrambles and shuffles them.
#include <cstdint>

namespace lucent {

constexpr int kSobolDimensions = 9;

// Point index's coordinate in dimension (0 <= dimension < kSobolDimensions).
uint32_t sobol(int dimension, uint32_t index);

}  // namespace lucent
