// Optically thick objects (SampleScheme::OpticallyThick): no samples, each
// pixel's view ray marched with the light's way through the medium read from
// entry maps of the mesh (runtime/internal/thick_pass.h). Each case is lit where
// the closed form it replaced, the Lommel-Seeliger law under the pixel's own
// face, drew black: light entering a face the camera does not see and leaving
// through one it sees, and light crossing a thin part and the air behind it
// into the next. Held to ss's goal for the object's optical radius against
// the exact reference.
#include <gtest/gtest.h>

#include <cstdio>

#include "core/image_compare.h"
#include "preprocess/preprocessor.h"
#include "reference/reference_renderer.h"
#include "tests/runtime/ss_goal.h"
#include "tests/runtime/ss_helper.h"
#include "tests/support/test_support.h"

namespace lucent {
namespace {

// ss against the reference, the object preprocessed with so few samples that
// its light dies within a fraction of their spacing: optically thick.
ImageError thickAgainstReference(const SceneDesc& scene, int margin, double& goal) {
    std::vector<std::string> warnings;
    const auto objects = loadObjects(scene, warnings);
    PreprocessSettings settings = qualityPreset("draft");
    settings.samples = 50;
    const SampleSet samples = preprocessObject(objects[0], settings);
    EXPECT_EQ(samples.parameters.scheme, SampleScheme::OpticallyThick);
    writeSampleFile(objects[0].desc().samples, samples);
    ReferenceSettings reference;
    reference.tolerance = 1e-4;
    reference.surface = false;
    goal = test::ssGoalRelativeRmse(objects);
    return compareImages(test::renderSs(scene, false), ReferenceRenderer(scene, objects).render(reference), margin);
}

void report(const char* name, const ImageError& e, double goal) {
    std::printf("%s: relative RMSE %.4f over %zu pixels, mean ratio %.4f (goal %.2f)\n", name, e.relativeRmse, e.pixels,
                e.meanRatio, goal);
}

// sigma_t 80: light dies within 0.1 of the unit cube's faces. Lit from +x, the
// camera sees the front and top faces, and the light that crosses the edges
// from the face on the right: a bright line along them and nothing else.
TEST(OpticallyThick, ACubeLitFromBesideShowsTheLightAcrossItsEdges) {
    test::ScratchDir dir;
    SceneDesc scene;
    scene.camera = test::squareCamera(Vec3(0.0, 1.2, 5.0), Vec3(0.0), 40.0, 64);
    scene.lights = {test::pointLight(Vec3(4.0, -0.3, 0.0), Rgb(60.0))};
    ObjectDesc o = test::simpleObject(test::modelsDir() / "cube.obj", 80.0, 0.9);
    o.samples = dir.path() / "cube.lsf";
    scene.objects = {o};
    double goal = 0.0;
    const ImageError e = thickAgainstReference(scene, 0, goal);
    report("cube lit from beside", e, goal);
    EXPECT_GT(e.pixels, 20u);  // the edge's line
    EXPECT_LT(e.relativeRmse, goal);
    EXPECT_NEAR(e.meanRatio, 1.0, goal);
}

// Two plates 0.1 thick (0.8 mean free paths), 0.6 apart, lit from behind: the
// near plate's seen face gets only light that crossed the far plate and the gap.
TEST(OpticallyThick, LightCrossesAThinPartAndTheAirBehindItIntoTheNext) {
    test::ScratchDir dir;
    std::string obj;
    char line[128];
    for (double z : {-0.4, 0.3}) {
        for (int k = 0; k < 8; ++k) {
            std::snprintf(line, sizeof line, "v %g %g %g\n", k & 1 ? 1.0 : -1.0, k & 2 ? 1.0 : -1.0,
                          k & 4 ? z + 0.1 : z);
            obj += line;
        }
    }
    for (int base : {0, 8}) {
        const int f[12][3] = {{1, 3, 4}, {1, 4, 2}, {5, 6, 8}, {5, 8, 7}, {1, 2, 6}, {1, 6, 5},
                              {3, 7, 8}, {3, 8, 4}, {1, 5, 7}, {1, 7, 3}, {2, 4, 8}, {2, 8, 6}};
        for (const auto& t : f) {
            std::snprintf(line, sizeof line, "f %d %d %d\n", t[0] + base, t[1] + base, t[2] + base);
            obj += line;
        }
    }
    SceneDesc scene;
    scene.camera = test::squareCamera(Vec3(0.8, 1.2, 4.5), Vec3(0.0), 35.0, 64);
    scene.lights = {test::pointLight(Vec3(0.5, 0.5, -4.0), Rgb(60.0))};
    ObjectDesc o = test::simpleObject(dir.write("plates.obj", obj), 8.0, 0.9);
    o.samples = dir.path() / "plates.lsf";
    scene.objects = {o};
    double goal = 0.0;
    const ImageError e = thickAgainstReference(scene, 2, goal);
    report("two plates lit from behind", e, goal);
    EXPECT_GT(e.pixels, 1000u);
    EXPECT_LT(e.relativeRmse, goal);
    EXPECT_NEAR(e.meanRatio, 1.0, goal);
}

}  // namespace
}  // namespace lucent
