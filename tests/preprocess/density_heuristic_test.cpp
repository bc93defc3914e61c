#include "preprocess/density_heuristic.h"

#include <gtest/gtest.h>

#include "core/rng.h"
#include "core/sphere_directions.h"
#include "tests/support/test_support.h"

namespace lucent {
namespace {

HeuristicSettings settingsFor(double sigma) {
    HeuristicSettings s;
    s.directions = 256;
    s.step = 0.01;
    s.extinction = sigma;
    return s;
}

TEST(DensityHeuristic, FirstMomentPointsOutAlongTheNormalOfALargeSphere) {
    // sigma_t = 20: the sphere is 20 mean free paths in radius, "large" to the light.
    std::vector<std::string> warnings;
    const VolumeObject sphere(test::simpleObject(test::modelsDir() / "sphere.obj", 20.0), warnings);
    Rng rng(5, 5);
    std::vector<Vec3> points;
    for (int i = 0; i < 40; ++i) {
        const Vec3 n = randomRotation(rng) * Vec3(0, 0, 1);
        points.push_back((1.0 - 0.02 - 0.1 * rng.uniform()) * n);
    }
    const auto moments = sampleFirstMoments(sphere, points, settingsFor(20.0));
    for (size_t i = 0; i < points.size(); ++i) {
        const Vec3 T = moments.stencils[i].moment[0];
        EXPECT_GT(glm::dot(glm::normalize(T), glm::normalize(points[i])), 0.99) << i;
    }
}

TEST(DensityHeuristic, LargerNearTheSurface) {
    std::vector<std::string> warnings;
    const VolumeObject sphere(test::simpleObject(test::modelsDir() / "sphere.obj", 5.0), warnings);
    std::vector<Vec3> points;
    const Vec3 n = glm::normalize(Vec3(0.3, 0.5, 0.8));
    for (double depth : {0.02, 0.05, 0.1, 0.2, 0.4}) points.push_back((1.0 - depth) * n);
    const auto rho = divergenceDensity(sampleFirstMoments(sphere, points, settingsFor(5.0)), settingsFor(5.0));
    for (size_t i = 1; i < rho.size(); ++i) EXPECT_GT(rho[i - 1].density, rho[i].density) << "depth index " << i;
    for (size_t i = 1; i < rho.size(); ++i) EXPECT_GT(rho[i - 1].receivable, rho[i].receivable);
}

TEST(DensityHeuristic, LargerNearCornersThanFaces) {
    std::vector<std::string> warnings;
    const VolumeObject cube(test::simpleObject(test::modelsDir() / "cube.obj", 4.0), warnings);
    const double d = 0.1;  // the same distance to the nearest face
    const std::vector<Vec3> points = {Vec3(0, 0, 1 - d), Vec3(1 - d, 1 - d, 1 - d), Vec3(0, 1 - d, 1 - d)};
    const auto rho = divergenceDensity(sampleFirstMoments(cube, points, settingsFor(4.0)), settingsFor(4.0));
    EXPECT_GT(rho[1].density, rho[0].density);  // corner > face
    EXPECT_GT(rho[2].density, rho[0].density);  // edge > face
}

TEST(DensityHeuristic, CullsDeepPoints) {
    std::vector<std::string> warnings;
    const VolumeObject sphere(test::simpleObject(test::modelsDir() / "sphere.obj", 30.0), warnings);
    HeuristicSettings s = settingsFor(30.0);
    s.cullEpsilon = 1e-3;
    const std::vector<Vec3> points = {Vec3(0, 0, 0.98), Vec3(0, 0, 0.0)};
    const auto rho = divergenceDensity(sampleFirstMoments(sphere, points, s), s);
    EXPECT_FALSE(rho[0].culled);
    EXPECT_TRUE(rho[1].culled);
    // A point under a half-space at depth d receives E_2(sigma d) / 2 of full light.
    EXPECT_NEAR(rho[1].receivable, std::exp(-30.0), 1e-12);
}

}  // namespace
}  // namespace lucent
