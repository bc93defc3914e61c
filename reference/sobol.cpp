#include "reference/sobol.h"

#include <array>

namespace lucent {
namespace {

// A primitive polynomial of degree s over GF(2) with inner coefficients a (its
// bits, highest first) and the first s direction numbers m_1..m_s.
struct Polynomial {
    int s;
    uint32_t a;
    std::array<uint32_t, 5> m;
};

// Joe and Kuo's dimensions 2 to 9 (their dimension 1 is van der Corput's).
constexpr Polynomial kPolynomials[kSobolDimensions - 1] = {
    {1, 0, {1}},          {2, 1, {1, 3}},        {3, 1, {1, 3, 1}},        {3, 2, {1, 1, 1}},
    {4, 1, {1, 1, 3, 3}}, {4, 4, {1, 3, 5, 13}}, {5, 2, {1, 1, 5, 5, 17}}, {5, 4, {1, 1, 5, 5, 5}}};

// Direction numbers v_k = m_k 2^(32-k), by Bratley and Fox's recurrence
// m_k = 2 a_1 m_{k-1} ^ 4 a_2 m_{k-2} ^ ... ^ 2^s m_{k-s} ^ m_{k-s}.
std::array<uint32_t, 32> directionNumbers(int dimension) {
    std::array<uint32_t, 32> v{};
    if (dimension == 0) {
        for (int k = 0; k < 32; ++k) v[k] = 1u << (31 - k);
        return v;
    }
    const Polynomial& p = kPolynomials[dimension - 1];
    uint32_t m[33] = {};
    for (int k = 1; k <= p.s; ++k) m[k] = p.m[k - 1];
    for (int k = p.s + 1; k <= 32; ++k) {
        uint32_t x = m[k - p.s] ^ (m[k - p.s] << p.s);
        for (int j = 1; j < p.s; ++j)
            if ((p.a >> (p.s - 1 - j)) & 1u) x ^= m[k - j] << j;
        m[k] = x;
    }
    for (int k = 1; k <= 32; ++k) v[k - 1] = m[k] << (32 - k);
    return v;
}

// Each dimension's generator applied to one byte of the index at a time: the
// point is the xor of four table entries.
struct ByteTables {
    uint32_t table[kSobolDimensions][4][256];
    ByteTables() {
        for (int d = 0; d < kSobolDimensions; ++d) {
            const std::array<uint32_t, 32> v = directionNumbers(d);
            for (int byte = 0; byte < 4; ++byte)
                for (uint32_t b = 0; b < 256; ++b) {
                    uint32_t x = 0;
                    for (int k = 0; k < 8; ++k)
                        if ((b >> k) & 1u) x ^= v[8 * byte + k];
                    table[d][byte][b] = x;
                }
        }
    }
};

const ByteTables& tables() {
    static const ByteTables t;
    return t;
}

}  // namespace

uint32_t sobol(int dimension, uint32_t index) {
    const auto& t = tables().table[dimension];
    return t[0][index & 255u] ^ t[1][(index >> 8) & 255u] ^ t[2][(index >> 16) & 255u] ^ t[3][index >> 24];
}

}  // namespace lucent
