// The path sampler's stratified flights against their definition: each of a
// pixel's first 2^k paths falls in its own stratum of width 2^-k in every
// stratified flight, the flights of one path are uncorrelated, the values are
// uniform over many pixels, and past the stratified flights they are the
// pixel's plain stream.
#include "reference/path_sampler.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <vector>

namespace lucent {
namespace {

TEST(PathSampler, EachFlightPutsOnePathInEachStratum) {
    for (uint64_t pixel : {0ull, 7ull, 123456ull}) {
        for (int paths : {16, 256}) {
            PathSampler sampler(3, pixel);
            std::vector<std::set<int>> strata(PathSampler::kStratifiedFlights);
            for (int i = 0; i < paths; ++i) {
                sampler.startPath(uint32_t(i));
                for (int f = 0; f < PathSampler::kStratifiedFlights; ++f) {
                    const double u = sampler.flightUniform();
                    ASSERT_GE(u, 0.0);
                    ASSERT_LT(u, 1.0);
                    strata[f].insert(int(u * paths));
                }
            }
            for (int f = 0; f < PathSampler::kStratifiedFlights; ++f)
                EXPECT_EQ(int(strata[f].size()), paths) << "flight " << f << ", " << paths << " paths";
        }
    }
}

TEST(PathSampler, FlightsAreUniformAndUncorrelated) {
    // Over 4096 pixels of 16 paths: the mean of each flight's u is 1/2 and the
    // correlation of flights 0 and 1 within a path is 0, each within 4 standard
    // errors of independent uniforms (1 / sqrt(12 n) and 1 / sqrt(n)).
    const int pixels = 4096, paths = 16, n = pixels * paths;
    double sum0 = 0.0, sum1 = 0.0, product = 0.0;
    for (int p = 0; p < pixels; ++p) {
        PathSampler sampler(11, uint64_t(p));
        for (int i = 0; i < paths; ++i) {
            sampler.startPath(uint32_t(i));
            const double u0 = sampler.flightUniform(), u1 = sampler.flightUniform();
            sum0 += u0;
            sum1 += u1;
            product += (u0 - 0.5) * (u1 - 0.5);
        }
    }
    EXPECT_NEAR(sum0 / n, 0.5, 4.0 / std::sqrt(12.0 * n));
    EXPECT_NEAR(sum1 / n, 0.5, 4.0 / std::sqrt(12.0 * n));
    EXPECT_NEAR(12.0 * product / n, 0.0, 4.0 / std::sqrt(double(n)));
}

TEST(PathSampler, BeyondTheStratifiedFlightsAndUnstratifiedItIsThePlainStream) {
    Rng rng(5, 9);
    PathSampler plain{Rng(5, 9)};
    for (int i = 0; i < 20; ++i) EXPECT_EQ(plain.flightUniform(), rng.uniform());
    PathSampler sampler(5, 9);
    sampler.startPath(3);
    for (int f = 0; f < PathSampler::kStratifiedFlights; ++f) sampler.flightUniform();
    const double next = sampler.flightUniform();
    EXPECT_GE(next, 0.0);
    EXPECT_LT(next, 1.0);
}

}  // namespace
}  // namespace lucent
