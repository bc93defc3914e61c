#include "preprocess/density_heuristic.h"

#include <gtest/gtest.h>

#include "core/rng.h"
#include "core/sphere_directions.h"
#include "tests/support/test_support.h"

namespace lucent {
namespace {

struct Heuristic {
    Heuristic(const std::string& model, double sigma, double voxel, double depth, int directions = 128)
        : object(test::simpleObject(test::modelsDir() / model, sigma), warnings),
          distance(DistanceField::create(object.mesh(), voxel, depth)) {
        settings.directions = directions;
        settings.extinction = sigma;
        field = sampleFirstMoment(object, *distance, settings);
    }
    std::vector<HeuristicPoint> at(const std::vector<Vec3>& points) { return field->densityAtPoints(points, settings); }
    Vec3 firstMoment(const Vec3& x) const { return field->firstMomentAt(x); }
    std::vector<std::string> warnings;
    VolumeObject object;
    std::unique_ptr<DistanceField> distance;
    HeuristicSettings settings;
    std::unique_ptr<HeuristicField> field;
};

TEST(DensityHeuristic, FirstMomentPointsOutAlongTheNormalOfALargeSphere) {
    // sigma_t = 20: the sphere is 20 mean free paths in radius, "large" to the light.
    Heuristic h("sphere.obj", 20.0, 0.03, 0.2, 64);
    Rng rng(5, 5);
    for (int i = 0; i < 40; ++i) {
        const Vec3 n = randomRotation(rng) * Vec3(0, 0, 1);
        const Vec3 x = (1.0 - 0.03 - 0.1 * rng.uniform()) * n;
        EXPECT_GT(glm::dot(glm::normalize(h.firstMoment(x)), n), 0.99) << i;
    }
}

TEST(DensityHeuristic, DivergenceIsExtinctionTimesReceivableLight) {
    // Along every ray w . grad tau(x, w) = -sigma_t, hence div T = sigma_t * integral
    // exp(-tau) dw: an exact identity that the central differences must reproduce.
    const double sigma = 3.0;
    Heuristic h("sphere.obj", sigma, 0.04, 0.45, 128);
    std::vector<Vec3> points;
    Rng rng(8, 8);
    for (int i = 0; i < 60; ++i)
        points.push_back((0.95 - 0.35 * rng.uniform()) * (randomRotation(rng) * Vec3(0, 0, 1)));
    const auto rho = h.at(points);
    for (size_t i = 0; i < points.size(); ++i) {
        const double expected = sigma * 4 * kPi * rho[i].receivable;
        EXPECT_NEAR(rho[i].density, expected, 0.05 * expected) << "|x| = " << glm::length(points[i]);
    }
}

TEST(DensityHeuristic, LargerNearTheSurface) {
    Heuristic h("sphere.obj", 5.0, 0.03, 0.45, 64);
    std::vector<Vec3> points;
    const Vec3 n = glm::normalize(Vec3(0.3, 0.5, 0.8));
    for (double depth : {0.03, 0.06, 0.1, 0.2, 0.4}) points.push_back((1.0 - depth) * n);
    const auto rho = h.at(points);
    for (size_t i = 1; i < rho.size(); ++i) EXPECT_GT(rho[i - 1].density, rho[i].density) << "depth index " << i;
    for (size_t i = 1; i < rho.size(); ++i) EXPECT_GT(rho[i - 1].receivable, rho[i].receivable);
}

TEST(DensityHeuristic, LargerNearCornersThanFaces) {
    Heuristic h("cube.obj", 4.0, 0.03, 0.15, 64);
    const double d = 0.1;  // the same distance to the nearest face
    const auto rho = h.at({Vec3(0, 0, 1 - d), Vec3(1 - d, 1 - d, 1 - d), Vec3(0, 1 - d, 1 - d)});
    EXPECT_GT(rho[1].density, rho[0].density);  // corner > face
    EXPECT_GT(rho[2].density, rho[0].density);  // edge > face
    EXPECT_GT(rho[1].density, rho[2].density);  // corner > edge
}

TEST(DensityHeuristic, CullsWhatReceivesNoLight) {
    Heuristic h("sphere.obj", 10.0, 0.03, 0.62, 32);
    const auto rho = h.at({Vec3(0, 0, 0.91), Vec3(0, 0, 0.4)});  // sigma d = 0.9 and 6
    EXPECT_FALSE(rho[0].culled);
    EXPECT_TRUE(rho[1].culled);
    // The exact receivable light on the axis of a sphere, by a 1D quadrature over the
    // polar angle of the closed-form chord: (1/2) int_-1^1 exp(-sigma L(mu)) dmu.
    double exact = 0.0;
    const int n = 20000;
    for (int i = 0; i < n; ++i) {
        const double mu = -1.0 + (i + 0.5) * 2.0 / n, b = 0.91 * mu, c = 0.91 * 0.91 - 1.0;
        exact += std::exp(-10.0 * (-b + std::sqrt(b * b - c))) / n;
    }
    // 5%: Monte Carlo with 32 directions and the trilinear read between voxels.
    EXPECT_NEAR(rho[0].receivable, exact, 0.05 * exact);
}

}  // namespace
}  // namespace lucent
