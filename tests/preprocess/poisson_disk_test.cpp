#include "preprocess/poisson_disk.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include "core/rng.h"

namespace lucent {
namespace {

// A unit square in the z = 0 plane cut into 2 n^2 triangles, with a radius that
// grows along x from rMin to rMax.
RadiusSurface square(int n, double rMin, double rMax) {
    RadiusSurface s;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
            s.positions.emplace_back(double(i) / n, double(j) / n, 0.0);
            s.radius.push_back(rMin + (rMax - rMin) * double(i) / n);
        }
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const uint32_t a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
            s.triangles.push_back({a, b, d});
            s.triangles.push_back({a, d, c});
        }
    return s;
}

void expectPoissonAndMaximal(const RadiusSurface& surface, double rMin, double rMax, double finest) {
    const auto samples = poissonDiskSample(surface, 11, finest);
    ASSERT_GT(samples.size(), 10u);
    // No two samples closer than the larger of their radii.
    for (size_t i = 0; i < samples.size(); ++i)
        for (size_t j = i + 1; j < samples.size(); ++j) {
            const double d = glm::length(samples[i].position - samples[j].position);
            EXPECT_GE(d, std::max(samples[i].radius, samples[j].radius) * (1 - 1e-12)) << i << "," << j;
        }
    // Maximal: every point of the square is within (its own or the sample's) radius,
    // plus at most the finest fragment size, of some sample.
    Rng rng(2, 3);
    double worst = 0.0;
    for (int k = 0; k < 5000; ++k) {
        const Vec3 x(rng.uniform(), rng.uniform(), 0.0);
        const double rx = rMin + (rMax - rMin) * x.x;
        double best = kInfinity;
        for (const auto& s : samples) best = std::min(best, glm::length(x - s.position) / std::max(rx, s.radius));
        worst = std::max(worst, best);
    }
    EXPECT_LT(worst, 1.0 + finest / rMin);
}

TEST(PoissonDisk, ConstantRadiusIsPoissonAndMaximal) {
    expectPoissonAndMaximal(square(20, 0.05, 0.05), 0.05, 0.05, 0.01);
}

TEST(PoissonDisk, VaryingRadiusIsPoissonAndMaximal) {
    expectPoissonAndMaximal(square(40, 0.02, 0.08), 0.02, 0.08, 0.004);
}

TEST(PoissonDisk, DenserWhereRadiusIsSmaller) {
    const auto samples = poissonDiskSample(square(40, 0.02, 0.08), 7, 0.004);
    size_t left = 0, right = 0;
    for (const auto& s : samples) (s.position.x < 0.5 ? left : right)++;
    EXPECT_GT(left, 2 * right);
}

TEST(PoissonDisk, SameSeedSameSamples) {
    const auto a = poissonDiskSample(square(10, 0.05, 0.1), 3, 0.01);
    const auto b = poissonDiskSample(square(10, 0.05, 0.1), 3, 0.01);
    ASSERT_EQ(a.size(), b.size());
    for (size_t i = 0; i < a.size(); ++i) EXPECT_EQ(a[i].position, b[i].position);
}

// Tiles of one parity class take their darts at once: the samples must not
// depend on how many threads take them. The square spans about 50 tiles a side.
TEST(PoissonDisk, SameSamplesForAnyThreadCount) {
    auto sampleWith = [](int threads) {
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
        return poissonDiskSample(square(200, 0.002, 0.004), 9, 0.0004);
    };
    const auto one = sampleWith(1), two = sampleWith(2);
    ASSERT_GT(one.size(), 10000u);
    ASSERT_EQ(one.size(), two.size());
    for (size_t i = 0; i < one.size(); ++i) ASSERT_EQ(one[i].position, two[i].position) << i;
}

}  // namespace
}  // namespace lucent

namespace lucent {
namespace {

// One large triangle and thousands of tiny ones far from it. Fragments are drawn
// by rejection against the largest area a level has held: once the large one
// was gone, each draw among the tiny ones took ~1e8 tries, and thin-tube meshes
// (a torus knot's offset layers) spun for minutes. The sampler must finish and
// cover every tiny triangle.
TEST(PoissonDisk, FinishesOnceTheLargeFragmentsAreGone) {
    RadiusSurface s;
    s.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
    s.triangles = {{0, 1, 2}};
    const int side = 140;  // 19600 tiny triangles, 1e-4 across, 1e-3 apart, at z = 1
    for (int i = 0; i < side; ++i)
        for (int j = 0; j < side; ++j) {
            const Vec3 o(1e-3 * i, 1e-3 * j, 1.0);
            const uint32_t k = uint32_t(s.positions.size());
            s.positions.insert(s.positions.end(), {o, o + Vec3(1e-4, 0, 0), o + Vec3(0, 1e-4, 0)});
            s.triangles.push_back({k, k + 1, k + 2});
        }
    s.radius.assign(s.positions.size(), 0.02);
    const auto samples = poissonDiskSample(s, 5, 0.004);
    size_t onTiny = 0;
    for (const DiskSample& d : samples) onTiny += d.position.z > 0.5;
    // The 0.14 x 0.14 patch needs about (0.14 / 0.02)^2 / 1.5 disks of radius 0.02, give or take.
    EXPECT_GT(onTiny, 10u);
    for (size_t t = 1; t < s.triangles.size(); t += 97) {
        const Vec3 c = s.positions[s.triangles[t][0]];
        bool covered = false;
        for (const DiskSample& d : samples) covered = covered || glm::length(d.position - c) < d.radius + 1e-4;
        EXPECT_TRUE(covered) << "tiny triangle " << t;
    }
}

TEST(PoissonDisk, StopsAtItsBudget) {
    RadiusSurface s;
    s.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
    s.triangles = {{0, 1, 2}};
    s.radius.assign(3, 0.01);
    EXPECT_GT(poissonDiskSample(s, 1, 0.002).size(), 1000u);
    EXPECT_EQ(poissonDiskSample(s, 1, 0.002, 100).size(), 100u);
}

}  // namespace
}  // namespace lucent
