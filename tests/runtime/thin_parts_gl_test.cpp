// Thin parts (issue 13): a plate about one sample radius thick and a thin tube,
// each against the exact reference, held to ss's goal for its optical radius
// 2 px inside the silhouette (the rim, where a pixel straddles the edge of a
// part one or two pixels across, is not what is measured here). Before the
// weights counted the far side of thin regions and widened the Gaussians there,
// the plate was at 9.8% and grainy (docs/accuracy.md, Thin parts).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "core/image_compare.h"
#include "preprocess/preprocessor.h"
#include "reference/reference_renderer.h"
#include "tests/runtime/ss_goal.h"
#include "tests/runtime/ss_helper.h"
#include "tests/support/test_support.h"

namespace lucent {
namespace {

// A torus about the z axis: the tube of radius minor around the circle of radius major.
std::string torusObj(double major, double minor, int around, int across) {
    std::string obj;
    char line[160];
    for (int i = 0; i < around; ++i)
        for (int j = 0; j < across; ++j) {
            const double u = 2.0 * kPi * i / around, v = 2.0 * kPi * j / across;
            std::snprintf(line, sizeof line, "v %.12f %.12f %.12f\n", (major + minor * std::cos(v)) * std::cos(u),
                          (major + minor * std::cos(v)) * std::sin(u), minor * std::sin(v));
            obj += line;
        }
    for (int i = 0; i < around; ++i)
        for (int j = 0; j < across; ++j) {
            const int a = i * across + j + 1, b = (i + 1) % around * across + j + 1;
            const int c = (i + 1) % around * across + (j + 1) % across + 1, d = i * across + (j + 1) % across + 1;
            std::snprintf(line, sizeof line, "f %d %d %d\nf %d %d %d\n", a, b, c, a, c, d);
            obj += line;
        }
    return obj;
}

struct ThinCase {
    const char* name;
    Vec3 camera, target;
};

double errorOf(const std::filesystem::path& mesh, const ThinCase& c, const test::ScratchDir& dir) {
    SceneDesc scene;
    scene.camera = test::squareCamera(c.camera, c.target, 35, 128);
    scene.lights = {test::pointLight(Vec3(2, 3, 3), Rgb(40.0))};
    ObjectDesc o = test::simpleObject(mesh, 8.0, 0.75);
    o.samples = dir.path() / "thin.lsf";
    scene.objects = {o};
    const ImageError e = test::ssAgainstReference(scene, 2);
    std::vector<std::string> warnings;
    const double goal = test::ssGoalRelativeRmse(loadObjects(scene, warnings));
    std::printf("%s: relative RMSE %.4f over %zu pixels, mean ratio %.4f (goal %.2f)\n", c.name, e.relativeRmse,
                e.pixels, e.meanRatio, goal);
    EXPECT_GT(e.pixels, 2000u);
    return e.relativeRmse / goal;
}

TEST(ThinParts, APlateAboutOneSampleRadiusThickMeetsTheGoal) {
    test::ScratchDir dir;
    const auto mesh = test::writeBox(dir, "plate.obj", Vec3(-1, -1, -0.006), Vec3(1, 1, 0.006));
    EXPECT_LT(errorOf(mesh, {"plate 0.012 thick", Vec3(0.8, 1.2, 4.5), Vec3(0.0)}, dir), 1.0);
}

// Four radii thick: below 5.5 radii across the Gaussians are widened too
// (preprocess/internal/sample_description.cpp, kThinWidening); at 3 radii this plate was at 5.9%.
TEST(ThinParts, APlateFourSampleRadiiThickMeetsTheGoal) {
    test::ScratchDir dir;
    const auto mesh = test::writeBox(dir, "plate.obj", Vec3(-1, -1, -0.03), Vec3(1, 1, 0.03));
    EXPECT_LT(errorOf(mesh, {"plate 0.06 thick", Vec3(0.8, 1.2, 4.5), Vec3(0.0)}, dir), 1.0);
}

TEST(ThinParts, AThinTubeMeetsTheGoal) {
    test::ScratchDir dir;
    const auto mesh = dir.write("tube.obj", torusObj(0.8, 0.06, 256, 24));
    EXPECT_LT(errorOf(mesh, {"tube 0.12 across, seen close", Vec3(1.25, -0.55, 0.35), Vec3(0.8, 0, 0)}, dir), 1.0);
}

}  // namespace
}  // namespace lucent
