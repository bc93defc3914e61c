// --method lbl and --method mdom end to end (OpenCL on PoCL, OpenGL on Mesa)
// against --method path, the independent ground truth of full transport: the
// goal of the first hybrid issue is at most 20% relative RMSE at albedo 0.8 for
// lbl, that of --method auto 10% (docs/accuracy.md) for mdom, and both clearly
// closer to the path tracer than single scattering alone. At albedo 0 nothing
// scatters twice, so they must add nothing to ss.
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

struct Renders {
    Image ss, lbl, path;  // lbl: the method under test
};

Renders renderSphere(double sigmaT, double albedo, int pathSamples, const std::string& method = "lbl", double g = 0.0,
                     double ior = 1.0, const std::map<std::string, double>& extra = {}) {
    SceneDesc scene;
    scene.file = "sphere.json";
    scene.camera = test::squareCamera(Vec3(0, 0, 5), Vec3(0), 30, 32);
    scene.lights = {test::pointLight(Vec3(3, 3, 3), Rgb(40.0))};
    scene.objects = {test::simpleObject(test::modelsDir() / "sphere.obj", sigmaT, albedo)};
    scene.objects[0].medium.g = g;
    scene.objects[0].medium.ior = ior;
    LoadedScene loaded = loadScene(scene, false);
    PreprocessSettings pre = qualityPreset("draft");
    attachSamples(loaded, {preprocessObject(loaded.objects[0], pre)});
    MethodSettings settings;
    settings.surface = false;
    const auto run = [&](const std::string& name, const std::map<std::string, double>& values) {
        const MethodEntry& entry = findMethod(name);
        MethodOptions options(entry.options);
        for (const auto& [option, value] : values) options.set(option, value);
        return renderWith(entry, *entry.create(options), loaded, settings);
    };
    Renders r;
    r.ss = run("ss", {});
    std::map<std::string, double> options = extra;
    options["grid"] = 40;
    if (method == "mdom") options["directions"] = 24;
    r.lbl = run(method, options);
    if (pathSamples > 0) r.path = run("path", {{"samples", pathSamples}});
    return r;
}

TEST(LblMethod, WithinTheGoalOfThePathTracerAndFarCloserThanSingleScattering) {
    const Renders r = renderSphere(2.0, 0.8, 2048);
    const double lbl = luminanceRelativeRmse(r.lbl, r.path), ss = luminanceRelativeRmse(r.ss, r.path);
    std::printf("lbl %.4f ss %.4f\n", lbl, ss);
    EXPECT_LE(lbl, 0.20);
    EXPECT_LT(lbl, 0.5 * ss) << "ss " << ss;
}

TEST(MdomMethod, WithinTheGoalOfThePathTracerAndFarCloserThanSingleScattering) {
    const Renders r = renderSphere(2.0, 0.8, 2048, "mdom");
    const double mdom = luminanceRelativeRmse(r.lbl, r.path), ss = luminanceRelativeRmse(r.ss, r.path);
    std::printf("mdom %.4f ss %.4f\n", mdom, ss);
    EXPECT_LE(mdom, 0.10);
    EXPECT_LT(mdom, 0.25 * ss) << "ss " << ss;
}

TEST(MdomMethod, AnImageStreamedThroughADevicePoolIsTheWholeGridsImage) {
    // A 40^3 grid is 8 blocks of at most 32^3: 50% holds 4 at a time, 5% one.
    // At ior 1.4 the sweeps reflect on the object's faces, also where those
    // lie on a block's border.
    const Image whole = renderSphere(2.0, 0.8, 0, "mdom", 0.5, 1.4).lbl;
    double largest = 0.0;
    for (const auto& p : whole.pixels) largest = std::max(largest, double(glm::length(glm::vec3(p))));
    ASSERT_GT(largest, 0.0);
    for (double pool : {50.0, 5.0}) {
        const Image pooled = renderSphere(2.0, 0.8, 0, "mdom", 0.5, 1.4, {{"device-pool", pool}}).lbl;
        ASSERT_EQ(pooled.pixels.size(), whole.pixels.size());
        double worst = 0.0;
        for (size_t i = 0; i < whole.pixels.size(); ++i)
            worst = std::max(worst, double(glm::length(glm::vec3(pooled.pixels[i] - whole.pixels[i]))));
        EXPECT_LE(worst, 1e-5 * largest) << "a pool of " << pool << "%";
    }
}

TEST(MdomMethod, WarnsWhereItMissesTheGoal) {
    // Past g 0.8 mdom misses the goal (docs/accuracy.md); the user is told in one line.
    SceneDesc scene;
    scene.objects = {test::simpleObject(test::modelsDir() / "sphere.obj", 2.0, 0.8)};
    scene.objects[0].medium.g = 0.9;
    const LoadedScene loaded = loadScene(scene, false);
    const auto warnings = findMethod("mdom").createDefault()->limitations(loaded, MethodSettings{});
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("|g| > 0.8"), std::string::npos) << warnings[0];
    EXPECT_EQ(warnings[0].find('\n'), std::string::npos);
    scene.objects[0].medium.g = 0.8;
    EXPECT_TRUE(findMethod("mdom").createDefault()->limitations(loadScene(scene, false), MethodSettings{}).empty());
}

TEST(LblMethod, AddsNothingWhereNothingScattersTwice) {
    for (const char* method : {"lbl", "mdom"}) {
        const Renders r = renderSphere(2.0, 0.0, 0, method);
        double most = 0;
        for (size_t i = 0; i < r.ss.pixels.size(); ++i)
            for (int c = 0; c < 3; ++c) {
                most = std::max(most, double(r.ss.pixels[i][c]));
                ASSERT_EQ(r.lbl.pixels[i][c], r.ss.pixels[i][c]) << method << " " << i;
            }
        EXPECT_EQ(most, 0.0);  // and ss itself is black: albedo 0 scatters nothing at all
    }
}

TEST(LblMethod, FiniteAtAlbedoOneAndEnormousExtinction) {
    struct Case {
        const char* method;
        double sigmaT, g;
    };
    for (const Case& k : {Case{"lbl", 1e-4, 0.0}, Case{"lbl", 2.0, 0.0}, Case{"lbl", 1e4, 0.0}, Case{"mdom", 1e-4, 0.0},
                          Case{"mdom", 2.0, 0.999}, Case{"mdom", 2.0, -0.999}, Case{"mdom", 1e4, 0.9}}) {
        const double sigmaT = k.sigmaT;
        const Renders r = renderSphere(sigmaT, 1.0, 0, k.method, k.g);
        size_t bad = 0;
        double sum = 0;
        for (const auto& p : r.lbl.pixels)
            for (int c = 0; c < 3; ++c) {
                bad += !(std::isfinite(p[c]) && p[c] >= 0.0f);
                sum += p[c];
            }
        EXPECT_EQ(bad, 0u) << k.method << " " << sigmaT << " g " << k.g;
        EXPECT_GT(sum, 0.0) << k.method << " " << sigmaT << " g " << k.g;
    }
}

}  // namespace
}  // namespace lucent
