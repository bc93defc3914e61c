// The single scattering drawn at half and quarter resolution and upsampled along
// the objects' depth (DrawOptions::scatterScale, upsample.frag) must keep ss's
// accuracy: against the reference, 2 px inside the silhouette, within ss's goal
// for the object's optical radius, and no more than one point of relative RMSE
// above the full-resolution pass (the speed item's "error unchanged"). A sphere,
// and a torus: a hole, inner walls where the depth steps, and a silhouette inside.
#include <gtest/gtest.h>

#include "core/image_compare.h"
#include "preprocess/preprocessor.h"
#include "reference/reference_renderer.h"
#include "runtime/offscreen_context.h"
#include "runtime/offscreen_frame.h"
#include "runtime/scattering_renderer.h"
#include "tests/runtime/ss_goal.h"
#include "tests/support/test_support.h"

namespace lucent {
namespace {

class ReducedScattering : public ::testing::TestWithParam<const char*> {};

TEST_P(ReducedScattering, KeepsTheErrorOfTheFullResolution) {
    const int size = 384;
    SceneDesc scene;
    scene.camera = test::squareCamera(Vec3(0.4, 2.5, 4.5), Vec3(0.0), 35, size);
    scene.lights = {test::pointLight(Vec3(3, 3, 3), Rgb(40.0))};
    scene.objects = {test::simpleObject(test::modelsDir() / GetParam(), 2.0, 0.75)};
    std::vector<std::string> warnings;
    const auto objects = loadObjects(scene, warnings);
    const SampleSet samples = preprocessObject(objects[0], qualityPreset("default"));
    ReferenceSettings rs;
    rs.surface = false;
    const Image reference = ReferenceRenderer(scene, objects).render(rs);

    const auto context = OffscreenContext::create(GlBackend::Auto);
    OffscreenFrame frame(size, size);
    ScatteringRenderer renderer;
    renderer.addObject(translucentObjectFor(objects[0], samples));
    renderer.setLights(scene.lights);
    const ViewSetup view = viewSetupFor(scene.camera, objects[0].mesh().bounds());
    double full = 0.0;
    for (int scale : {1, 2, 4}) {
        DrawOptions options;
        options.surface = false;
        options.scatterScale = scale;
        frame.bindAndClear();
        renderer.draw(view, options);
        const ImageError e = compareImages(frame.read(), reference, 2);
        std::printf("%s at 1/%d: relative RMSE %.4f over %zu pixels\n", GetParam(), scale, e.relativeRmse, e.pixels);
        EXPECT_GT(e.pixels, 5000u);
        EXPECT_LT(e.relativeRmse, test::ssGoalRelativeRmse(objects));
        if (scale == 1)
            full = e.relativeRmse;
        else
            EXPECT_LT(e.relativeRmse, full + 0.01) << "at 1/" << scale;
    }
}

INSTANTIATE_TEST_SUITE_P(Shapes, ReducedScattering, ::testing::Values("sphere.obj", "torus.obj"));

}  // namespace
}  // namespace lucent
