#include "preprocess/sh_projection.h"

#include <gtest/gtest.h>

#include "core/spherical_harmonics.h"
#include "core/rng.h"
#include "core/sphere_directions.h"
#include "tests/support/test_support.h"

namespace lucent {
namespace {

TEST(ShProjection, CentreOfHomogeneousSphereIsConstant) {
    std::vector<std::string> warnings;
    const VolumeObject sphere(test::simpleObject(test::modelsDir() / "sphere.obj", 2.0), warnings);
    ProjectionSettings s;
    const auto r = projectAttenuation(sphere, {Vec3(0)}, {}, s, 1);
    // exp(-2 * 1) in every direction: only c_00 = sqrt(4 pi) exp(-2).
    EXPECT_NEAR(r.coefficients[0], std::sqrt(4 * kPi) * std::exp(-2.0), 2e-3);
    for (int k = 1; k < 25; ++k) EXPECT_NEAR(r.coefficients[k], 0.0, 2e-3);
    EXPECT_LT(r.truncationError[0], 1e-3);
}

TEST(ShProjection, ReconstructsAttenuationOffCentre) {
    std::vector<std::string> warnings;
    const VolumeObject sphere(test::simpleObject(test::modelsDir() / "sphere.obj", 0.5), warnings);
    ProjectionSettings s;
    s.order = 5;
    s.directions = 1024;
    const Vec3 x(0.2, -0.3, 0.1);
    const auto r = projectAttenuation(sphere, {x}, {}, s, 1);
    std::vector<double> c(r.coefficients.begin(), r.coefficients.end());
    Rng rng(1, 1);
    for (int i = 0; i < 50; ++i) {
        const Vec3 w = randomRotation(rng) * Vec3(0, 0, 1);
        const double b = glm::dot(x, w), cc = glm::dot(x, x) - 1.0;
        const double exact = std::exp(-0.5 * (-b + std::sqrt(b * b - cc)));
        EXPECT_NEAR(reconstructSh(5, c, w), exact, 0.01 * exact);
    }
    EXPECT_LT(r.truncationError[0], 1e-3);
}

TEST(ShProjection, ColouredMediumProjectsEachChannel) {
    std::vector<std::string> warnings;
    ObjectDesc desc = test::simpleObject(test::modelsDir() / "sphere.obj", 1.0);
    desc.medium.sigmaT = Rgb(1.0, 2.0, 4.0);
    const VolumeObject sphere(desc, warnings);
    const auto r = projectAttenuation(sphere, {Vec3(0)}, {}, ProjectionSettings{}, 3);
    ASSERT_EQ(r.coefficients.size(), 75u);
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(r.coefficients[c * 25], std::sqrt(4 * kPi) * std::exp(-desc.medium.sigmaT[c]), 2e-3);
}

TEST(ShProjection, TruncationErrorGrowsWithPeakiness) {
    // Just under the surface of a very dense sphere exp(-tau) is a narrow lobe
    // around the normal that 25 coefficients cannot hold; in a thin medium it is smooth.
    std::vector<std::string> warnings;
    const VolumeObject dense(test::simpleObject(test::modelsDir() / "sphere.obj", 1000.0), warnings);
    const VolumeObject thin(test::simpleObject(test::modelsDir() / "sphere.obj", 2.0), warnings);
    const Vec3 x(0, 0, 0.97);
    const float peaky = projectAttenuation(dense, {x}, {}, ProjectionSettings{}, 1).truncationError[0];
    const float smooth = projectAttenuation(thin, {x}, {}, ProjectionSettings{}, 1).truncationError[0];
    EXPECT_GT(peaky, 0.2f);
    EXPECT_LT(smooth, 0.01f);
}

}  // namespace
}  // namespace lucent

namespace lucent {
namespace {

// The exit distance out of a ball, against the quadratic formula for a sphere of
// radius R about the ball's centre, and against d / cos for the half-space.
TEST(BoundaryBall, ExitDistanceMatchesTheSphereAndThePlane) {
    Rng rng(3, 0);
    for (double radius : {0.5, 1.0, 40.0}) {
        for (double depth : {1e-4, 0.05, 0.3}) {
            if (depth >= radius) continue;
            for (int i = 0; i < 200; ++i) {
                const Vec3 w = randomRotation(rng) * Vec3(0, 0, 1);
                const Vec3 n(0, 0, 1);
                const Vec3 x = (radius - depth) * n;  // relative to the ball's centre
                const double b = glm::dot(x, w), c = glm::dot(x, x) - radius * radius;
                const double exact = -b + std::sqrt(b * b - c);
                EXPECT_NEAR(ballExitDistance(w.z, depth, 1.0 / radius), exact, 1e-9 * radius) << radius << " " << depth;
            }
        }
    }
    for (double cosine : {1.0, 0.3, 1e-3}) {
        EXPECT_DOUBLE_EQ(ballExitDistance(cosine, 0.2, 0.0), 0.2 / cosine);
        // A barely curved ball is the half-space, without cancellation.
        EXPECT_NEAR(ballExitDistance(cosine, 0.2, 1e-12), 0.2 / cosine, 1e-6 * 0.2 / cosine);
    }
    EXPECT_EQ(ballExitDistance(-0.5, 0.2, 0.0), kInfinity);
}

// Near the surface of a dense sphere exp(-tau) steps down at the horizon, which
// order-5 SH smear; the sphere's own boundary ball holds it, leaving the SH a
// remainder that they reconstruct to within a few per cent of full light.
TEST(BoundaryBall, HoldsTheHorizonTheShCannot) {
    std::vector<std::string> warnings;
    const double sigmaT = 8.0;
    const VolumeObject sphere(test::simpleObject(test::modelsDir() / "sphere.obj", sigmaT), warnings);
    const Vec3 x(0.0, 0.0, 0.97);
    BoundaryBall ball;
    ball.normal = glm::vec3(0, 0, 1);
    ball.depth = 0.03f;
    ball.curvature = 1.0f;
    ProjectionSettings s;
    s.directions = 1024;
    const auto withBall = projectAttenuation(sphere, {x}, {ball}, s, 1);
    const auto shOnly = projectAttenuation(sphere, {x}, {}, s, 1);
    EXPECT_GT(withBall.balls[0].share, 0.9f);
    std::vector<double> cBall(withBall.coefficients.begin(), withBall.coefficients.end());
    std::vector<double> cSh(shOnly.coefficients.begin(), shOnly.coefficients.end());
    Rng rng(5, 0);
    double worstBall = 0.0, worstSh = 0.0;
    for (int i = 0; i < 200; ++i) {
        const Vec3 w = randomRotation(rng) * Vec3(0, 0, 1);
        const double b = glm::dot(x, w), cc = glm::dot(x, x) - 1.0;
        const double exact = std::exp(-sigmaT * (-b + std::sqrt(b * b - cc)));  // unit sphere, exact chord
        const double viaBall = withBall.balls[0].share * ballTransmittance(Rgb(sigmaT), withBall.balls[0], w).r +
                               reconstructSh(5, cBall, w);
        worstBall = std::max(worstBall, std::abs(viaBall - exact));
        worstSh = std::max(worstSh, std::abs(reconstructSh(5, cSh, w) - exact));
    }
    EXPECT_LT(worstBall, 0.05);
    EXPECT_GT(worstSh, 4.0 * worstBall);
    EXPECT_LT(withBall.truncationError[0], 0.1 * shOnly.truncationError[0]);
}

}  // namespace
}  // namespace lucent
