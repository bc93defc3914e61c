// A host adds, removes and updates objects between frames: after each change
// the frame is the one a renderer given that state from the start draws.
#include <gtest/gtest.h>

#include "core/error.h"
#include "core/image_compare.h"
#include "preprocess/preprocessor.h"
#include "runtime/offscreen_context.h"
#include "runtime/offscreen_frame.h"
#include "runtime/scattering_renderer.h"
#include "tests/support/test_support.h"

namespace lucent {
namespace {

TEST(RendererObjects, RemovingAndGivingNewSamplesMatchARendererBuiltThatWay) {
    SceneDesc scene;
    scene.camera.width = scene.camera.height = 64;
    Light bulb, behindLeft;
    bulb.position = Vec3(3, 3, 3);
    bulb.power = Rgb(40.0);
    // Its light crosses the left box on the way to the right one: the right box's
    // traced light must change when the left one goes.
    behindLeft.position = Vec3(-6.0, 0.1, 0.05);
    behindLeft.power = Rgb(40.0);
    scene.lights = {bulb, behindLeft};
    test::ScratchDir dir;
    ObjectDesc left =
        test::simpleObject(test::writeBox(dir, "left.obj", Vec3(-1.2, -0.4, -0.4), Vec3(-0.4, 0.4, 0.4)), 2.0, 0.8);
    ObjectDesc right =
        test::simpleObject(test::writeBox(dir, "right.obj", Vec3(0.4, -0.4, -0.4), Vec3(1.2, 0.4, 0.4)), 2.0, 0.8);
    ObjectDesc denser = right;
    denser.medium.sigmaT = Rgb(5.0);
    scene.objects = {left, right, denser};
    std::vector<std::string> warnings;
    const auto objects = loadObjects(scene, warnings);
    PreprocessSettings settings = qualityPreset("draft");
    settings.samples = 1500;
    std::vector<SampleSet> samples;
    for (const VolumeObject& o : objects) samples.push_back(preprocessObject(o, settings));

    const auto context = OffscreenContext::create(GlBackend::Auto);
    OffscreenFrame frame(64, 64);
    Bounds3 bounds;
    for (const VolumeObject& o : objects) bounds.extend(o.mesh().bounds().min), bounds.extend(o.mesh().bounds().max);
    const ViewSetup view = viewSetupFor(scene.camera, bounds);
    // The lights are set once, before the objects change: what each change
    // invalidates must be redone by the change itself.
    auto draw = [&](ScatteringRenderer& r) {
        frame.bindAndClear();
        r.draw(view);
        return frame.read();
    };
    ScatteringRenderer changing;
    changing.setLights(scene.lights);
    changing.addObject(translucentObjectFor(objects[0], samples[0]));
    changing.addObject(translucentObjectFor(objects[1], samples[1]));
    const Image both = draw(changing);
    changing.removeObject(0);
    EXPECT_EQ(changing.objectCount(), 1u);
    const Image removed = draw(changing);
    changing.setSamples(0, samples[2], &objects[2]);  // the right box's medium made denser, preprocessed again
    const Image updated = draw(changing);
    EXPECT_THROW(changing.removeObject(1), Error);

    ScatteringRenderer rightOnly, denserOnly;
    rightOnly.addObject(translucentObjectFor(objects[1], samples[1]));
    denserOnly.addObject(translucentObjectFor(objects[2], samples[2]));
    rightOnly.setLights(scene.lights);
    denserOnly.setLights(scene.lights);
    EXPECT_LT(compareImages(removed, draw(rightOnly)).relativeRmse, 1e-6);
    EXPECT_LT(compareImages(updated, draw(denserOnly)).relativeRmse, 1e-6);
    EXPECT_GT(compareImages(removed, both).relativeRmse, 0.1) << "removing the left box changed nothing";
    EXPECT_GT(compareImages(updated, removed).relativeRmse, 0.1) << "new samples changed nothing";
}

}  // namespace
}  // namespace lucent
