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
    const auto r = projectAttenuation(sphere, {Vec3(0)}, s, 1);
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
    const auto r = projectAttenuation(sphere, {x}, s, 1);
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
    const auto r = projectAttenuation(sphere, {Vec3(0)}, ProjectionSettings{}, 3);
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
    const float peaky = projectAttenuation(dense, {x}, ProjectionSettings{}, 1).truncationError[0];
    const float smooth = projectAttenuation(thin, {x}, ProjectionSettings{}, 1).truncationError[0];
    EXPECT_GT(peaky, 0.2f);
    EXPECT_LT(smooth, 0.01f);
}

}  // namespace
}  // namespace lucent
