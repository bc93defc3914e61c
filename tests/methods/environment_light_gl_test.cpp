// The environment light in every method, against answers independent of them:
// - the white furnace, scattered part: an index-matched object of albedo 1 under
//   a uniform environment L scatters towards the eye L (1 - e^{-sigma_t c}), c
//   the chord of the pixel's ray through it (what is not scattered arrives
//   unscattered, L e^{-sigma_t c}, and "background": false leaves that out);
// - single scattering (ss) against the reference, which
//   tests/reference/environment_light_test.cpp checks against a quadrature;
// - a one-texel patch draws the image of the directional light of its irradiance,
//   also through ss's SH projection of the environment (--light sh).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>

#include "core/camera_rays.h"
#include "core/environment_map.h"
#include "core/image_compare.h"
#include "core/loaded_scene.h"
#include "methods/method_table.h"
#include "preprocess/preprocessor.h"
#include "tests/support/test_support.h"

namespace lucent {
namespace {

LoadedScene sphere(double albedo, int size, double g = 0.0) {
    SceneDesc desc;
    desc.file = "sphere.json";
    desc.camera = test::squareCamera(Vec3(0.0, 0.0, 5.0), Vec3(0.0), 30.0, size);
    desc.objects = {test::simpleObject(test::modelsDir() / "sphere.obj", 2.0, albedo)};
    desc.objects[0].medium.g = g;
    LoadedScene scene = loadScene(desc, false);
    attachSamples(scene, {preprocessObject(scene.objects[0], qualityPreset("draft"))});
    return scene;
}

Image render(const LoadedScene& scene, const std::string& name, const std::map<std::string, double>& values,
             const std::string& light = "traced") {
    const MethodEntry& entry = findMethod(name);
    MethodOptions options(entry.options);
    for (const auto& [option, value] : values) options.set(option, value);
    if (name == "ss") options.set("light", light);
    MethodSettings settings;
    settings.surface = false;
    return renderWith(entry, *entry.create(options), scene, settings);
}

const std::map<std::string, double> kLbl{{"grid", 40}}, kMdom{{"grid", 40}, {"directions", 24}};

// Relative RMSE over the pixels whose ray crosses at least half the sphere's radius.
double furnaceError(const Image& image, const LoadedScene& scene, double L) {
    const CameraRays rays(scene.desc.camera);
    const VolumeObject& o = scene.objects[0];
    std::vector<Interval> inside;
    double squared = 0.0, truth = 0.0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            o.boundary().insideIntervals(rays.origin(), rays.direction(x + 0.5, y + 0.5), kInfinity, inside, false);
            double chord = 0.0;
            for (const Interval& i : inside) chord += i.t1 - i.t0;
            if (chord < 0.5) continue;
            const double want = L * (1.0 - std::exp(-2.0 * chord)), got = image.at(x, y).g;
            squared += (got - want) * (got - want);
            truth += want * want;
        }
    return std::sqrt(squared / truth);
}

EnvironmentMap uniformMap(double L) {
    Image image(8, 4);
    for (auto& p : image.pixels) p = glm::vec3(float(L));
    return EnvironmentMap(image, 1.0, glm::dmat3(1.0));
}

// The goal of lbl and mdom against the path tracer, and the path tracer within 5% (its noise at 256 paths, 3%).
TEST(EnvironmentLight, TheScatteredWhiteFurnaceMeetsEachMethodsGoal) {
    LoadedScene scene = sphere(1.0, 32);
    scene.environment = std::make_shared<EnvironmentMap>(uniformMap(1.0));
    for (const auto& [name, values, goal] : std::vector<std::tuple<std::string, std::map<std::string, double>, double>>{
             {"path", {{"samples", 256}}, 0.05}, {"lbl", kLbl, 0.10}, {"mdom", kMdom, 0.10}}) {
        const double e = furnaceError(render(scene, name, values), scene, 1.0);
        std::printf("%s: %.2f%% from L (1 - e^-sigma c)\n", name.c_str(), 100.0 * e);
        EXPECT_LT(e, goal) << name;
    }
}

std::shared_ptr<EnvironmentMap> skyWithASun() {
    Image sky(64, 32);
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 64; ++x)
            sky.at(x, y) = y < 16 ? glm::vec3(0.3f, 0.45f, 0.8f) : glm::vec3(0.15f, 0.12f, 0.1f);
    sky.at(8, 10) = glm::vec3(400.0f, 380.0f, 340.0f);
    return std::make_shared<EnvironmentMap>(sky, 1.0, glm::dmat3(1.0));
}

// ss's goal at the sphere's optical radius 2 (docs/accuracy.md), under a sky with a sun.
TEST(EnvironmentLight, SsMeetsItsGoalAgainstTheReferenceUnderASkyWithASun) {
    LoadedScene scene = sphere(0.8, 32);
    scene.environment = skyWithASun();
    const Image reference = render(scene, "reference", {});
    const double e = compareImages(render(scene, "ss", {}), reference, 2).relativeRmse;
    std::printf("ss: %.2f%% from the reference\n", 100.0 * e);
    EXPECT_LT(e, 0.10);
}

// --light sh projects the environment onto SH per sample (ScatteringRenderer::setEnvironment):
// 1 band when isotropic, 5 at g = 0.3, 8 at g = 0.5. The same goal in each.
TEST(EnvironmentLight, SsFromTheShMeetsItsGoalUnderASkyWithASunAtEachBandCount) {
    for (double g : {0.0, 0.3, 0.5}) {
        LoadedScene scene = sphere(0.8, 32, g);
        scene.environment = skyWithASun();
        const Image reference = render(scene, "reference", {});
        const double e = compareImages(render(scene, "ss", {}, "sh"), reference, 2).relativeRmse;
        std::printf("ss --light sh, g %.1f: %.2f%% from the reference\n", g, 100.0 * e);
        EXPECT_LT(e, 0.10) << g;
    }
}

TEST(EnvironmentLight, AOneTexelPatchDrawsItsDirectionalLightsImageInEveryFastMethod) {
    const int width = 256, height = 128, x = 32, y = 40;
    const double solidAngle = 2.0 * kPi / width * (std::cos(kPi * y / height) - std::cos(kPi * (y + 1) / height));
    Image patch(width, height);
    patch.at(x, y) = glm::vec3(float(3.0 / solidAngle));
    LoadedScene lit = sphere(0.8, 24), withPatch = sphere(0.8, 24);
    withPatch.environment = std::make_shared<EnvironmentMap>(patch, 1.0, glm::dmat3(1.0));
    const double t = kPi * (y + 0.5) / height, p = 2.0 * kPi * (x + 0.5) / width;
    Light sun;
    sun.type = Light::Type::Directional;
    sun.direction = -Vec3(std::sin(t) * std::cos(p), std::cos(t), -std::sin(t) * std::sin(p));
    sun.power = Rgb(3.0);
    lit.desc.lights = {sun};
    for (const auto& [name, values] : std::vector<std::pair<std::string, std::map<std::string, double>>>{
             {"ss", {}}, {"lbl", kLbl}, {"mdom", kMdom}}) {
        const double e = compareImages(render(withPatch, name, values), render(lit, name, values), 2).relativeRmse;
        std::printf("%s: patch against directional %.3f%%\n", name.c_str(), 100.0 * e);
        // The patch's directions spread over its texel, 0.7 degrees: a small share of a pixel's light.
        EXPECT_LT(e, 0.02) << name;
    }
    // Projected onto the SH (--light sh): the projection's directions and convention.
    const double e = compareImages(render(withPatch, "ss", {}, "sh"), render(lit, "ss", {}, "sh"), 2).relativeRmse;
    std::printf("ss --light sh: patch against directional %.3f%%\n", 100.0 * e);
    EXPECT_LT(e, 0.02);
}

}  // namespace
}  // namespace lucent
