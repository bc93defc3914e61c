// The Lucent scheme's blockers: psi is projected with them filled by the medium
// and, with --light sh, the runtime shadows each light with their shadow maps
// (runtime/internal/blocker_shadows.h); the traced light stops at them
// (runtime/internal/traced_light.h). In the torus cube, where the reference says the
// torus's shadow takes most of the light (pixels at under 0.6 of the same cube
// without the torus), ss must be as dark as the reference either way; without
// the maps it is about three times brighter there.
#include <gtest/gtest.h>

#include "core/sample_set.h"
#include "preprocess/preprocessor.h"
#include "reference/reference_renderer.h"
#include "tests/runtime/ss_helper.h"
#include "tests/support/test_support.h"

namespace lucent {
namespace {

Image reference(const SceneDesc& scene) {
    std::vector<std::string> warnings;
    const auto objects = loadObjects(scene, warnings);
    ReferenceSettings settings;
    settings.tolerance = 1e-3;
    settings.surface = false;
    return ReferenceRenderer(scene, objects).render(settings);
}

void expectShadowMatchesTheReference(const Light& light) {
    test::ScratchDir dir;
    SceneDesc scene = parseScene(test::modelsDir() / "torus-cube.json");
    scene.camera.width = scene.camera.height = 96;
    scene.lights = {light};
    for (auto& o : scene.objects) o.samples = dir.path() / o.samples.filename();
    std::vector<std::string> warnings;
    const auto objects = loadObjects(scene, warnings);
    PreprocessSettings settings = qualityPreset("default");
    settings.samples = 20000;
    for (const auto& o : objects) writeSampleFile(o.desc().samples, preprocessObject(o, settings));
    const Image shadowed = reference(scene);
    SceneDesc open = scene;
    for (auto& o : open.objects) o.medium.blockers.clear();
    const Image unshadowed = reference(open);
    for (bool traced : {true, false}) {
        const Image lucent = test::renderSs(scene, false, "", traced);
        double ssSum = 0.0, referenceSum = 0.0;
        size_t pixels = 0;
        for (size_t i = 0; i < shadowed.pixels.size(); ++i) {
            const float r = shadowed.pixels[i].r, free = unshadowed.pixels[i].r;
            if (!(r < 0.6f * free && r > 0.05f * free)) continue;
            ssSum += lucent.pixels[i].r;
            referenceSum += r;
            ++pixels;
        }
        std::printf("%s light: %zu shadowed pixels, ss / reference %.3f\n", traced ? "traced" : "sh", pixels,
                    ssSum / referenceSum);
        ASSERT_GT(pixels, 40u);
        EXPECT_NEAR(ssSum / referenceSum, 1.0, 0.3) << (traced ? "traced" : "sh, shadow maps");
    }
}

TEST(BlockerShadows, PointLightShadowMatchesTheReference) {
    const Light light = test::pointLight(Vec3(0.5, -0.3, -4.0), Rgb(60.0));
    expectShadowMatchesTheReference(light);
}

TEST(BlockerShadows, DirectionalLightShadowMatchesTheReference) {
    Light light;
    light.type = Light::Type::Directional;
    light.direction = glm::normalize(Vec3(-0.1, 0.06, 1.0));
    light.power = Rgb(4.0);
    expectShadowMatchesTheReference(light);
}

}  // namespace
}  // namespace lucent
