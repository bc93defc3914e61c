// Sphere lights in every method. As the radius shrinks each method's image
// tends to its image under the point light; with a radius, a blocker casts a
// soft shadow, which ss and the path tracer (single scattering) draw as the
// reference does by integrating the light's cone, and lbl and mdom as the path
// tracer does in full transport.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>

#include "core/image_compare.h"
#include "core/loaded_scene.h"
#include "methods/method_table.h"
#include "preprocess/preprocessor.h"
#include "tests/support/test_support.h"

namespace lucent {
namespace {

struct Slab {
    test::ScratchDir dir;
    LoadedScene scene;
};

// A slab of sigma_t 4 lit from above; with a blocker, an opaque plate under the
// top face over x < 0, whose edge throws the shadow across the middle.
std::unique_ptr<Slab> slab(bool blocker) {
    auto s = std::make_unique<Slab>();
    SceneDesc scene;
    scene.file = "slab.json";
    scene.camera = test::squareCamera(Vec3(0.0, 6.0, 0.0), Vec3(0.0), 28.0, 32);
    scene.camera.up = Vec3(0.0, 0.0, -1.0);
    scene.lights = {test::pointLight(Vec3(0.0, 1.5, 0.0), Rgb(10.0))};
    ObjectDesc o =
        test::simpleObject(test::writeBox(s->dir, "slab.obj", Vec3(-1.6, -0.6, -1.6), Vec3(1.6, 0.0, 1.6)), 4.0, 0.3);
    if (blocker)
        o.medium.blockers = {test::writeBox(s->dir, "plate.obj", Vec3(-1.5, -0.25, -1.5), Vec3(0.0, -0.05, 1.5))};
    scene.objects = {o};
    s->scene = loadScene(scene, false);
    attachSamples(s->scene, {preprocessObject(s->scene.objects[0], qualityPreset("draft"))});
    return s;
}

Image render(LoadedScene& scene, const std::string& name, const std::map<std::string, double>& values, double radius) {
    const MethodEntry& entry = findMethod(name);
    MethodOptions options(entry.options);
    for (const auto& [option, value] : values) options.set(option, value);
    MethodSettings settings;
    settings.surface = false;
    scene.desc.lights[0].radius = radius;
    return renderWith(entry, *entry.create(options), scene, settings);
}

double meanOf(const Image& image) {
    double sum = 0.0;
    for (const auto& p : image.pixels) sum += p.g;
    return sum / double(image.pixels.size());
}

TEST(SphereLight, AVanishingRadiusGivesThePointLightsImageInEveryMethod) {
    auto s = slab(false);
    for (const auto& [name, values] : std::vector<std::pair<std::string, std::map<std::string, double>>>{
             {"reference", {}}, {"ss", {}}, {"lbl", {{"grid", 40}}}, {"mdom", {{"grid", 40}, {"directions", 24}}}}) {
        const Image point = render(s->scene, name, values, 0.0), sphere = render(s->scene, name, values, 1e-5);
        const double e = compareImages(sphere, point).relativeRmse;
        std::printf("%s: %.2e\n", name.c_str(), e);
        EXPECT_LT(e, 1e-4) << name;
    }
    // The path tracer draws two more random numbers per event for a sphere light: equal in the mean.
    const Image point = render(s->scene, "path", {{"samples", 64}}, 0.0),
                sphere = render(s->scene, "path", {{"samples", 64}}, 1e-5);
    EXPECT_NEAR(meanOf(sphere) / meanOf(point), 1.0, 0.02);
}

// How far a method's softening of the shadow (its image under the sphere light
// minus under the point light) is from the reference's, relative to the
// reference's image: the error the sphere light adds, with each method's own
// error, the same for both lights, taken out.
double softeningError(const Image& soft, const Image& hard, const Image& refSoft, const Image& refHard) {
    double squared = 0.0, reference = 0.0;
    for (size_t i = 0; i < soft.pixels.size(); ++i) {
        const double want = double(refSoft.pixels[i].g) - refHard.pixels[i].g;
        const double got = double(soft.pixels[i].g) - hard.pixels[i].g;
        squared += (got - want) * (got - want);
        reference += double(refSoft.pixels[i].g) * refSoft.pixels[i].g;
    }
    return std::sqrt(squared / reference);
}

// The goal: the sphere light adds at most a quarter of ss's 10% (docs/accuracy.md).
// Drawing it as a point would add the whole softening, 5% of this image.
TEST(SphereLight, SsAndThePathTracerSoftenTheShadowAsTheReferenceDoes) {
    auto s = slab(true);
    const Image soft = render(s->scene, "reference", {}, 1.0), hard = render(s->scene, "reference", {}, 0.0);
    const double none = softeningError(hard, hard, soft, hard);
    const double ss = softeningError(render(s->scene, "ss", {}, 1.0), render(s->scene, "ss", {}, 0.0), soft, hard);
    const std::map<std::string, double> single{{"samples", 256}, {"max-scatter", 1}};
    const double path =
        softeningError(render(s->scene, "path", single, 1.0), render(s->scene, "path", single, 0.0), soft, hard);
    std::printf("added by the sphere light: ss %.4f, path %.4f; as a point %.4f\n", ss, path, none);
    EXPECT_GT(none, 0.025);  // the softening is there to be drawn
    EXPECT_LT(ss, 0.025);
    EXPECT_LT(path, 0.025);
}

// lbl and mdom against full transport: their softening from the path
// tracer's, within the same quarter of their goal. lbl's photons and the path
// tracer are random: each draws the scene twice, and the difference of two
// softenings, twice a softening's noise, takes the noise out.
TEST(SphereLight, LblAndMdomSoftenTheShadowAsThePathTracerDoes) {
    auto s = slab(true);
    const auto draw = [&](const std::string& name, const std::map<std::string, double>& values, uint64_t seed,
                          double radius) {
        const MethodEntry& entry = findMethod(name);
        MethodOptions options(entry.options);
        for (const auto& [option, value] : values) options.set(option, value);
        MethodSettings settings;
        settings.surface = false;
        settings.seed = seed;
        s->scene.desc.lights[0].radius = radius;
        return renderWith(entry, *entry.create(options), s->scene, settings);
    };
    const std::map<std::string, double> paths{{"samples", 1024}};
    const Image soft = draw("path", paths, 1, 1.0), hard = draw("path", paths, 1, 0.0);
    const double pathNoise = softeningError(draw("path", paths, 2, 1.0), draw("path", paths, 2, 0.0), soft, hard);
    for (const auto& [name, values] : std::vector<std::pair<std::string, std::map<std::string, double>>>{
             {"lbl", {{"grid", 40}}}, {"mdom", {{"grid", 40}, {"directions", 24}}}}) {
        const Image mSoft = draw(name, values, 1, 1.0), mHard = draw(name, values, 1, 0.0);
        const double e = softeningError(mSoft, mHard, soft, hard);
        const double noise = softeningError(draw(name, values, 2, 1.0), draw(name, values, 2, 0.0), mSoft, mHard);
        const double bias = std::sqrt(std::max(e * e - (pathNoise * pathNoise + noise * noise) / 2.0, 0.0));
        std::printf(
            "added by the sphere light: %s %.4f (%.4f with the noise of its softening %.4f and the path "
            "tracer's %.4f)\n",
            name.c_str(), bias, e, noise / std::sqrt(2.0), pathNoise / std::sqrt(2.0));
        EXPECT_LT(bias, 0.025) << name;
    }
    std::printf("as a point: %.4f\n", softeningError(hard, hard, soft, hard));
}

}  // namespace
}  // namespace lucent
