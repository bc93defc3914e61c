// Sobol's generator against an independent tabulation of Joe and Kuo's
// direction numbers: the first eight columns of each dimension's generator
// matrix (the point of index 2^k is column k), and for the high bytes the
// last column of dimensions 1 and 2. The columns are copied from pbrt-v4,
// src/pbrt/util/sobolmatrices.cpp (L. Gruenschloss's matrices from
// new-joe-kuo-6.21201; entries 52 d + k of SobolMatrices32).
#include "reference/sobol.h"

#include <gtest/gtest.h>

#include <cstdint>

#include "core/rng.h"

namespace lucent {
namespace {

constexpr uint32_t kColumns[kSobolDimensions][8] = {
    {0x80000000, 0x40000000, 0x20000000, 0x10000000, 0x08000000, 0x04000000, 0x02000000, 0x01000000},
    {0x80000000, 0xc0000000, 0xa0000000, 0xf0000000, 0x88000000, 0xcc000000, 0xaa000000, 0xff000000},
    {0x80000000, 0xc0000000, 0x60000000, 0x90000000, 0xe8000000, 0x5c000000, 0x8e000000, 0xc5000000},
    {0x80000000, 0xc0000000, 0x20000000, 0x50000000, 0xf8000000, 0x74000000, 0xa2000000, 0x93000000},
    {0x80000000, 0x40000000, 0x20000000, 0xb0000000, 0xf8000000, 0xdc000000, 0x7a000000, 0x9d000000},
    {0x80000000, 0x40000000, 0x60000000, 0x30000000, 0xc8000000, 0x24000000, 0x56000000, 0xfb000000},
    {0x80000000, 0xc0000000, 0xa0000000, 0xd0000000, 0x58000000, 0x94000000, 0x3e000000, 0xe3000000},
    {0x80000000, 0x40000000, 0xa0000000, 0x50000000, 0x88000000, 0x24000000, 0x12000000, 0x2d000000},
    {0x80000000, 0x40000000, 0xa0000000, 0x50000000, 0x28000000, 0xd4000000, 0x6a000000, 0x71000000}};

TEST(Sobol, GeneratorColumnsAreJoeAndKuos) {
    for (int d = 0; d < kSobolDimensions; ++d)
        for (int k = 0; k < 8; ++k)
            EXPECT_EQ(sobol(d, 1u << k), kColumns[d][k]) << "dimension " << d << ", column " << k;
    EXPECT_EQ(sobol(0, 1u << 31), 1u);
    EXPECT_EQ(sobol(1, 1u << 31), 0xffffffffu);
    EXPECT_EQ(sobol(2, 1u << 31), 0xc5005555u);
    EXPECT_EQ(sobol(3, 0), 0u);
}

TEST(Sobol, EachPointIsTheXorOfItsIndexBitsColumns) {
    // The generator is linear over GF(2) in every byte of the index.
    Rng rng(1, 2);
    for (int i = 0; i < 1000; ++i) {
        const uint32_t a = uint32_t(rng.nextU64()), b = uint32_t(rng.nextU64());
        for (int d = 0; d < kSobolDimensions; ++d) ASSERT_EQ(sobol(d, a ^ b), sobol(d, a) ^ sobol(d, b));
    }
}

}  // namespace
}  // namespace lucent
