// --method ss on a placed object (the scene's "transform"): the sample file of
// the object in its own space, read through a similarity the shaders apply.
// Two checks: against the reference of the placed object, held to ss's goal;
// and against the same renderer seeing the unplaced object from the camera and
// lights moved into the object's space, with sigma_t times the scale (the
// definition of the placement, computed by other means: no model matrix at all,
// and the optical depths scaled through DrawOptions::extinctionScale).
#include <gtest/gtest.h>

#include "core/image_compare.h"
#include "preprocess/preprocessor.h"
#include "reference/reference_renderer.h"
#include "runtime/offscreen_context.h"
#include "runtime/offscreen_frame.h"
#include "runtime/scattering_renderer.h"
#include "tests/runtime/ss_goal.h"
#include "tests/runtime/ss_helper.h"
#include "tests/support/test_support.h"

namespace lucent {
namespace {

const Similarity kPlacement = makeSimilarity(1.7, Vec3(1.0, 2.0, 3.0), 37.0, Vec3(0.4, -0.3, 0.25));

// A box of three density slabs along x, sigma_t 1.2, and its scene seen from
// the side with a point and a directional light.
struct PlacedBox {
    test::ScratchDir dir;
    SceneDesc scene;

    PlacedBox() {
        scene.camera = test::squareCamera(Vec3(1.0, 1.5, 6.0), kPlacement.translation, 30.0, 96);
        Light bulb, sun;
        bulb.position = Vec3(3.0, 3.0, 2.0);
        bulb.power = Rgb(40.0);
        sun.type = Light::Type::Directional;
        sun.direction = glm::normalize(Vec3(-1.0, -0.5, -0.3));
        sun.power = Rgb(1.5);
        scene.lights = {bulb, sun};
        ObjectDesc o =
            test::simpleObject(test::writeBox(dir, "box.obj", Vec3(-0.6, -0.5, -0.4), Vec3(0.6, 0.5, 0.4)), 1.2, 0.75);
        o.medium.density.type = DensityDesc::Type::Layers;
        o.medium.density.axis = 0;
        o.medium.density.values = {0.5, 1.0, 0.75};
        o.samples = dir.path() / "box.lsf";
        scene.objects = {o};
        // Preprocessed once, in the object's own space.
        std::vector<std::string> warnings;
        writeSampleFile(o.samples, preprocessObject(loadObjects(scene, warnings)[0], qualityPreset("default")));
        scene.objects[0].transform = kPlacement;
    }
};

TEST(PlacedObject, SsMeetsTheGoalOfItsOpticalRadiusWithoutNewPreprocessing) {
    PlacedBox box;
    std::vector<std::string> warnings;
    const auto placed = loadObjects(box.scene, warnings);
    const auto own = loadObjects(withoutTransforms(box.scene), warnings);
    ReferenceSettings reference;
    reference.tolerance = 1e-4;
    reference.surface = false;
    const ImageError e =
        compareImages(test::renderSs(box.scene, false), ReferenceRenderer(box.scene, placed).render(reference));
    // The optical radius grows with the scale: the object's own times 1.7.
    const double goal = test::ssGoalForOpticalRadius(test::opticalRadius(own[0]) * kPlacement.scale);
    std::printf("placed layered box: relative RMSE %.4f (goal %.2f), mean ratio %.4f\n", e.relativeRmse, goal,
                e.meanRatio);
    EXPECT_GT(e.pixels, 800u);
    EXPECT_LT(e.relativeRmse, goal);
}

TEST(PlacedObject, SsEqualsTheUnplacedObjectSeenFromTheObjectsOwnSpace) {
    PlacedBox box;
    const LoadedScene loaded = loadScene(withoutTransforms(box.scene), true);
    const Similarity& p = kPlacement;
    // The camera and the lights moved into the object's space: points by the
    // inverse, directions by the inverse rotation; a point light's intensity over
    // scale^2, so that I / d^2 is the same at the same place.
    SceneDesc own = loaded.desc;
    own.camera.position = p.inversePoint(box.scene.camera.position);
    own.camera.target = p.inversePoint(box.scene.camera.target);
    own.camera.up = p.inverseDirection(box.scene.camera.up);
    for (Light& l : own.lights) {
        if (l.type == Light::Type::Point) {
            l.position = p.inversePoint(l.position);
            l.power /= p.scale * p.scale;
        } else {
            l.direction = p.inverseDirection(l.direction);
        }
    }
    const auto context = OffscreenContext::create(GlBackend::Auto);
    const int size = box.scene.camera.width;
    OffscreenFrame frame(size, size);
    auto draw = [&](const SceneDesc& scene, ScatteringRenderer& renderer, const Bounds3& bounds,
                    float extinctionScale) {
        renderer.setLights(scene.lights);
        frame.bindAndClear();
        DrawOptions options;
        options.surface = false;
        options.extinctionScale = extinctionScale;
        renderer.draw(viewSetupFor(scene.camera, bounds), options);
        return frame.read();
    };
    Bounds3 placedBounds;
    for (const Vec3& v : loaded.objects[0].mesh().positions) placedBounds.extend(p.point(v));
    // The library's way: added where the file has it, then moved before a frame.
    ScatteringRenderer moved;
    moved.addObject(translucentObjectFor(loaded.objects[0], loaded.samples[0]));
    const Image before = draw(box.scene, moved, placedBounds, 1.0f);
    moved.setPlacement(0, p);
    const Image placedImage = draw(box.scene, moved, placedBounds, 1.0f);
    ScatteringRenderer unplaced;
    unplaced.addObject(translucentObjectFor(loaded.objects[0], loaded.samples[0]));
    const Image ownImage = draw(own, unplaced, loaded.bounds(), float(p.scale));
    const ImageError e = compareImages(placedImage, ownImage);
    std::printf("placed against own space: relative RMSE %.2e over %zu pixels\n", e.relativeRmse, e.pixels);
    EXPECT_GT(e.pixels, 800u);
    // Single precision and the depth range (near and far hug each scene) differ; nothing else may.
    EXPECT_LT(e.relativeRmse, 1e-3);
    EXPECT_GT(compareImages(before, placedImage).relativeRmse, 0.1) << "moving the object changed nothing";
}

}  // namespace
}  // namespace lucent
