// The lighting of the surface the camera sees, against its value on a cube
// worked out by hand (the warning ss gives with it: extremes_gl_test.cpp).
#include "runtime/grazing_light.h"

#include <gtest/gtest.h>

#include <cmath>

#include "tests/support/test_support.h"

namespace lucent {
namespace {

TriangleMesh cube() {
    std::vector<std::string> warnings;
    return loadClosedMesh(test::modelsDir() / "cube.obj", warnings);  // [-1, 1]^3
}

Light sun(const Vec3& towardLight) {
    Light l;
    l.type = Light::Type::Directional;
    l.direction = -glm::normalize(towardLight);
    l.power = Rgb(1.0);
    return l;
}

TEST(GrazingLight, TheSeenSurfacesMeanCosineOnACube) {
    const TriangleMesh box = cube();
    const Vec3 front(0.0, 0.0, 1e4), corner = 1e4 * Vec3(1.0, 1.0, 1.0);
    // From far in front only the +z face is seen; light 60 degrees off it meets it at cos 0.5.
    const double s60 = std::sin(glm::radians(60.0)), c60 = std::cos(glm::radians(60.0));
    EXPECT_NEAR(seenSurfaceLighting(box, front, {sun(Vec3(s60, 0.0, c60))}), 0.5, 1e-9);
    EXPECT_NEAR(seenSurfaceLighting(box, front, {sun(Vec3(0.0, 0.0, 1.0))}), 1.0, 1e-9);
    // From the side or behind, nothing the camera sees is lit.
    EXPECT_EQ(seenSurfaceLighting(box, front, {sun(Vec3(1.0, 0.0, 0.0))}), 0.0);
    EXPECT_EQ(seenSurfaceLighting(box, front, {sun(Vec3(0.3, 0.2, -1.0))}), 0.0);
    // From a corner three faces are seen alike, and light along +x lights one of them head-on.
    EXPECT_NEAR(seenSurfaceLighting(box, corner, {sun(Vec3(1.0, 0.0, 0.0))}), 1.0 / 3.0, 1e-6);
    // The best lit of several lights counts; a dark light and a spot aimed away count for nothing.
    Light dark = sun(Vec3(0.0, 0.0, 1.0)), away = test::pointLight(Vec3(0.0, 0.0, 4.0), Rgb(1.0));
    dark.power = Rgb(0.0);
    away.spot = SpotCone{Vec3(0.0, 0.0, 1.0), 10.0, 20.0};
    EXPECT_EQ(seenSurfaceLighting(box, front, {dark, away}), 0.0);
    EXPECT_NEAR(seenSurfaceLighting(box, front, {dark, away, sun(Vec3(s60, 0.0, c60))}), 0.5, 1e-9);
}

}  // namespace
}  // namespace lucent
