// The environment light in every method, against answers independent of them:
// - the white furnace: an index-matched object of albedo 1 under a uniform
//   environment L, with the background drawn, is L everywhere, seen through or
//   not: it scatters towards the eye L (1 - e^{-sigma_t c}), c the chord of the
//   pixel's ray through it, and lets L e^{-sigma_t c} through unscattered;
// - the unscattered part alone: an object that scatters nothing lets exactly
//   L e^{-sigma_t c} through, and "background": false leaves it out;
// - single scattering (ss) against the reference, which
//   tests/reference/environment_light_test.cpp checks against a quadrature;
// - a one-texel patch draws the image of the directional light of its irradiance,
//   also through ss's SH projection of the environment (--light sh).
#include <gtest/gtest.h>

#include <algorithm>
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

LoadedScene sphere(double albedo, int size, double g = 0.0, double ior = 1.0, double sigmaT = 2.0) {
    SceneDesc desc;
    desc.file = "sphere.json";
    desc.camera = test::squareCamera(Vec3(0.0, 0.0, 5.0), Vec3(0.0), 30.0, size);
    desc.objects = {test::simpleObject(test::modelsDir() / "sphere.obj", sigmaT, albedo)};
    desc.objects[0].medium.g = g;
    desc.objects[0].medium.ior = ior;
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

double chordThroughSphere(const LoadedScene& scene, int x, int y) {
    const CameraRays rays(scene.desc.camera);
    std::vector<Interval> inside;
    scene.objects[0].boundary().insideIntervals(rays.origin(), rays.direction(x + 0.5, y + 0.5), kInfinity, inside,
                                                false);
    double chord = 0.0;
    for (const Interval& i : inside) chord += i.t1 - i.t0;
    return chord;
}

// Relative RMSE against want(chord) over the pixels whose ray crosses at least
// half the sphere's radius, and the largest relative difference from
// outside over the pixels whose ray misses it.
struct FurnaceErrors {
    double inside = 0.0, outside = 0.0;
};
template <class Want>
FurnaceErrors furnaceErrors(const Image& image, const LoadedScene& scene, Want want, double outside) {
    double squared = 0.0, truth = 0.0;
    FurnaceErrors e;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const double chord = chordThroughSphere(scene, x, y), got = image.at(x, y).g;
            if (chord == 0.0) e.outside = std::max(e.outside, std::abs(got - outside) / outside);
            if (chord < 0.5) continue;
            squared += (got - want(chord)) * (got - want(chord));
            truth += want(chord) * want(chord);
        }
    e.inside = std::sqrt(squared / truth);
    return e;
}

EnvironmentMap uniformMap(double L) {
    Image image(8, 4);
    for (auto& p : image.pixels) p = glm::vec3(float(L));
    return EnvironmentMap(image, 1.0, glm::dmat3(1.0));
}

// The goal of lbl and mdom against the path tracer, and the path tracer within 5% (its noise at 256 paths, 3%).
// Where the ray misses the object, every method draws L itself (the path tracer to float rounding).
TEST(EnvironmentLight, TheWhiteFurnaceMeetsEachMethodsGoal) {
    LoadedScene scene = sphere(1.0, 32);
    scene.environment = std::make_shared<EnvironmentMap>(uniformMap(1.0));
    scene.desc.render.background = true;
    for (const auto& [name, values, goal] : std::vector<std::tuple<std::string, std::map<std::string, double>, double>>{
             {"path", {{"samples", 256}}, 0.05}, {"lbl", kLbl, 0.10}, {"mdom", kMdom, 0.10}}) {
        const FurnaceErrors e = furnaceErrors(
            render(scene, name, values), scene, [](double) { return 1.0; }, 1.0);
        std::printf("%s: %.2f%% from L where seen through, %.2g outside\n", name.c_str(), 100.0 * e.inside, e.outside);
        EXPECT_LT(e.inside, goal) << name;
        EXPECT_LT(e.outside, 1e-6) << name;
    }
}

// The unscattered environment that ss, lbl and mdom add to their scattering
// (core/environment_background.h), on an object that scatters nothing: exactly
// L e^{-sigma_t c} through it and L beside it; nothing with "background": false.
TEST(EnvironmentLight, SsLetsTheEnvironmentThroughAsBeersLawSays) {
    LoadedScene scene = sphere(0.0, 32);
    scene.environment = std::make_shared<EnvironmentMap>(uniformMap(2.0));
    const Image none = render(scene, "ss", {});
    EXPECT_EQ(*std::max_element(none.pixels.begin(), none.pixels.end(),
                                [](const glm::vec3& a, const glm::vec3& b) { return a.g < b.g; }),
              glm::vec3(0.0f));
    scene.desc.render.background = true;
    const FurnaceErrors e = furnaceErrors(
        render(scene, "ss", {}), scene, [](double c) { return 2.0 * std::exp(-2.0 * c); }, 2.0);
    std::printf("ss: %.2g from L e^-sigma c through, %.2g outside\n", e.inside, e.outside);
    EXPECT_LT(e.inside, 1e-5);
    EXPECT_LT(e.outside, 1e-6);
}

// Through a refracting object the environment bends and is mirrored: the ray
// splits at each boundary into a reflected and a refracted branch, each with
// its share. A clear object loses nothing, so under a uniform environment L
// every pixel sees L, through it or beside it; a wrong share, a crossing's
// n^2 wrong one way, or a branch lost shows as a pixel off L.
TEST(EnvironmentLight, AClearRefractingObjectUnderAUniformEnvironmentShowsItEverywhere) {
    LoadedScene scene = sphere(0.0, 16, 0.0, 1.5, 1e-6);
    scene.environment = std::make_shared<EnvironmentMap>(uniformMap(1.0));
    scene.desc.render.background = true;
    for (const std::string name : {"ss", "reference"}) {
        const Image image = render(scene, name, {});
        double worst = 0.0;
        for (const glm::vec3& p : image.pixels) worst = std::max(worst, std::abs(double(p.g) - 1.0));
        std::printf("%s: worst pixel %.2g from L\n", name.c_str(), worst);
        EXPECT_LT(worst, 1e-3) << name;
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
