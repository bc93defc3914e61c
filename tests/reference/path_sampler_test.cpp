// The path sampler's stratified flights against their definition: each of a
// pixel's first 2^k paths falls in its own stratum of width 2^-k in every
// stratified flight and direction, the first bounce's flight and direction are
// a (0, k, 2)-net (Sobol's first two dimensions, scrambled), the numbers of
// one path are uncorrelated, the values are uniform over many pixels, and
// past the stratified flights they are the pixel's plain stream.
#include "reference/path_sampler.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <utility>
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

// One path's draws in the order a path takes them: each joint bounce's flight
// then its direction, then the later flights alone.
std::vector<double> drawsOfOnePath(PathSampler& sampler) {
    std::vector<double> u;
    for (int f = 0; f < PathSampler::kStratifiedFlights; ++f) {
        u.push_back(sampler.flightUniform());
        if (f >= PathSampler::kJointBounces) continue;
        double a, b;
        sampler.directionUniforms(a, b);
        u.push_back(a);
        u.push_back(b);
    }
    return u;
}

TEST(PathSampler, TheFirstBounceIsANetAndEveryDrawIsStratified) {
    const int k = 8, paths = 1 << k;
    for (uint64_t pixel : {0ull, 5ull, 98765ull}) {
        PathSampler sampler(7, pixel);
        std::vector<std::vector<double>> draws;
        for (int i = 0; i < paths; ++i) {
            sampler.startPath(uint32_t(i));
            draws.push_back(drawsOfOnePath(sampler));
        }
        // Every elementary box 2^-a by 2^-(k-a) of (flight 0, direction u 0) holds one path.
        for (int a = 0; a <= k; ++a) {
            std::set<std::pair<int, int>> boxes;
            for (const std::vector<double>& u : draws) boxes.insert({int(u[0] * (1 << a)), int(u[1] * (1 << (k - a)))});
            EXPECT_EQ(int(boxes.size()), paths) << "boxes 2^-" << a << " by 2^-" << (k - a) << ", pixel " << pixel;
        }
        for (size_t d = 0; d < draws[0].size(); ++d) {
            std::set<int> strata;
            for (const std::vector<double>& u : draws) strata.insert(int(u[d] * paths));
            EXPECT_EQ(int(strata.size()), paths) << "draw " << d << ", pixel " << pixel;
        }
    }
}

TEST(PathSampler, ASecondDirectionAtOneFlightIsNotTheFirstAgain) {
    // Each dimension is used once in a path: the second draw takes plain
    // numbers, not the same point's coordinates (they would share its stratum
    // of width 2^-20, which plain numbers do with chance 2^-20).
    PathSampler sampler(3, 4);
    sampler.startPath(0);
    sampler.flightUniform();
    double a, b, c, d;
    sampler.directionUniforms(a, b);
    sampler.directionUniforms(c, d);
    EXPECT_NE(std::floor(a * 0x1.0p20), std::floor(c * 0x1.0p20));
    EXPECT_NE(std::floor(b * 0x1.0p20), std::floor(d * 0x1.0p20));
}

TEST(PathSampler, FlightsAreUniformAndUncorrelated) {
    // Over 4096 pixels of 16 paths: the mean of flight 0's u and of the first
    // direction's is 1/2 and their correlation within a path is 0, each within 4 standard
    // errors of independent uniforms (1 / sqrt(12 n) and 1 / sqrt(n)).
    const int pixels = 4096, paths = 16, n = pixels * paths;
    double sum0 = 0.0, sum1 = 0.0, product = 0.0;
    for (int p = 0; p < pixels; ++p) {
        PathSampler sampler(11, uint64_t(p));
        for (int i = 0; i < paths; ++i) {
            sampler.startPath(uint32_t(i));
            // Flight 0 against the first direction's first uniform (one Sobol point).
            const double u0 = sampler.flightUniform();
            double u1, unused;
            sampler.directionUniforms(u1, unused);
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
