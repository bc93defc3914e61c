// A sphere light's cone against its geometry worked out by hand.
#include "core/sphere_light.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/rng.h"

namespace lucent {
namespace {

TEST(SphereLight, TheConeIsTheSpheresAndItsLightTendsToThePointsAsItShrinks) {
    const Vec3 centre(1.0, 2.0, 3.0), x(1.0, 2.0, -1.0);  // d = 4
    const auto cone = sphereLightCone(centre, 2.0, x);    // half-angle 30 degrees
    ASSERT_TRUE(cone.has_value());
    EXPECT_NEAR(cone->cosMax, std::sqrt(3.0) / 2.0, 1e-15);
    EXPECT_EQ(cone->axis, Vec3(0.0, 0.0, 1.0));
    // L_e = I / (pi R^2) times the cone's solid angle 2 pi (1 - cos 30).
    EXPECT_NEAR(cone->irradiance, 2.0 * kPi * (1.0 - std::sqrt(3.0) / 2.0) / (kPi * 4.0), 1e-15);
    for (const double r : {1e-3, 1e-6, 1e-9}) {
        const auto small = sphereLightCone(centre, r, x);
        ASSERT_TRUE(small.has_value());
        EXPECT_NEAR(small->irradiance * 16.0, 1.0, r * r) << r;  // 1 / d^2
    }
    EXPECT_FALSE(sphereLightCone(centre, 4.0, x).has_value());  // on it
    EXPECT_FALSE(sphereLightCone(centre, 5.0, x).has_value());  // inside
    EXPECT_TRUE(sphereLightCone(centre, 0.0, x).has_value());
}

TEST(SphereLight, ConeDirectionsCoverTheConeUniformlyAndMeetTheSphere) {
    const Vec3 centre(0.0, 0.0, 4.0), x(0.0);
    const auto cone = sphereLightCone(centre, 2.0, x);
    ASSERT_TRUE(cone.has_value());
    Rng rng(3, 0);
    double meanCos = 0.0;
    const int n = 20000;
    for (int k = 0; k < n; ++k) {
        const Vec3 w = coneDirection(*cone, rng.uniform(), rng.uniform());
        EXPECT_NEAR(glm::length(w), 1.0, 1e-12);
        ASSERT_GE(w.z, cone->cosMax - 1e-12);
        // Every direction of the cone meets the sphere, at a point of it.
        const double t = distanceToSphere(x, w, centre, 2.0);
        EXPECT_NEAR(glm::length(x + t * w - centre), 2.0, 1e-6);
        meanCos += w.z / n;
    }
    // Uniform in solid angle: the mean cosine is the middle of [cos 30, 1].
    EXPECT_NEAR(meanCos, 0.5 * (1.0 + std::sqrt(3.0) / 2.0), 1e-3);
    EXPECT_NEAR(distanceToSphere(x, Vec3(0.0, 0.0, 1.0), centre, 2.0), 2.0, 1e-15);
}

}  // namespace
}  // namespace lucent
