// The method table: every built method listed once with a factory, auto
// resolved with its reason, and the loader's sample-set contract.
#include <gtest/gtest.h>

#include <set>

#include "core/error.h"
#include "core/loaded_scene.h"
#include "core/statistics.h"
#include "methods/method_table.h"
#include "preprocess/preprocessor.h"
#include "tests/support/test_support.h"

namespace lucent {
namespace {

TEST(MethodTable, NamesAreUniqueWithFactoriesAndAutoLast) {
    std::set<std::string> names;
    for (const MethodEntry& m : methodTable()) {
        EXPECT_TRUE(names.insert(m.name).second) << m.name;
        EXPECT_FALSE(m.summary.empty()) << m.name;
        EXPECT_TRUE(m.create && m.createDefault()) << m.name;
        EXPECT_EQ(m.unavailableReason(), "") << m.name;  // ss and reference run on any machine Lucent builds on
    }
    EXPECT_TRUE(names.count("ss") && names.count("reference"));
    const std::vector<std::string> all = methodNames();
    EXPECT_EQ(all.back(), "auto");
    EXPECT_EQ(all.size(), methodTable().size() + 1);
}

TEST(MethodTable, UnknownMethodsAreOneErrorListingTheBuiltOnes) {
    try {
        findMethod("dipole");
        FAIL() << "no error";
    } catch (const Error& e) {
#ifdef LUCENT_HAVE_OPENCL
        EXPECT_STREQ(e.what(),
                     "method 'dipole' is not built into this binary (built: ss, reference, path, lbl, mdom, auto)");
#else
        EXPECT_STREQ(e.what(), "method 'dipole' is not built into this binary (built: ss, reference, path, auto)");
#endif
    }
    SceneDesc scene;
    scene.file = "scene.json";
    try {
        resolveMethod("magic", scene);
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()).rfind("scene.json: /render/method: method 'magic' is not built", 0), 0u)
            << e.what();
    }
}

// Every option is declared once per name across the methods, with a default in
// its own domain and a line of help, so one flag means one thing.
TEST(MethodTable, OptionsAreDeclaredConsistentlyWithDefaultsInTheirDomain) {
    const std::vector<OfferedOption> offered = offeredOptions();  // throws on a conflict
    EXPECT_FALSE(offered.empty());
    for (const MethodEntry& m : methodTable()) {
        std::set<std::string> names;
        for (const OptionSpec& o : m.options) {
            EXPECT_TRUE(names.insert(o.name).second) << m.name << " --" << o.name;
            EXPECT_EQ(o.problem(o.defaultValue), "") << m.name;
            EXPECT_FALSE(o.help.empty()) << m.name << " --" << o.name;
            for (const char* shared : {"threads", "seed", "width", "height", "exposure", "method"})
                EXPECT_NE(o.name, shared) << m.name << " declares a shared option";
        }
    }
}

// A value for another method's option: an error when the user chose the method,
// a warning (and left out) when auto did.
TEST(MethodTable, ForeignOptionsAreAnErrorUnlessAutoChose) {
    std::vector<std::string> warnings;
    const MethodOptions path = methodOptions(findMethod("path"), {{"samples", "8"}}, false, warnings);
    EXPECT_EQ(path.integer("samples"), 8);
    EXPECT_TRUE(warnings.empty());
    try {
        methodOptions(findMethod("ss"), {{"samples", "8"}}, false, warnings);
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_STREQ(e.what(), "--samples is an option of --method path, not of ss");
    }
    const MethodOptions ss = methodOptions(findMethod("ss"), {{"samples", "8"}, {"light", "sh"}}, true, warnings);
    EXPECT_EQ(ss.choice("light"), "sh");
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_EQ(warnings[0], "--samples is an option of --method path, not of ss (chosen by auto): left out");
    EXPECT_THROW(methodOptions(findMethod("path"), {{"samples", "0"}}, false, warnings), Error);
}

// auto on scenes where each method is the right answer (the goal and the
// measured thresholds: docs/accuracy.md, "What auto picks").
SceneDesc sceneWith(const Rgb& albedo, int size, double g = 0.0) {
    SceneDesc scene;
    scene.camera.width = scene.camera.height = size;
    ObjectDesc o;
    o.medium.albedo = albedo;
    o.medium.g = g;
    scene.objects = {o};
    return scene;
}

TEST(MethodTable, AutoTakesTheReferenceForSmallImagesOfSingleScatteringOnSoftwareOpenGl) {
    const MethodChoice c = chooseMethod(sceneWith(Rgb(0.05), 64));
    EXPECT_EQ(c.method, openGlIsSoftware() ? "reference" : "ss") << c.reason;
    EXPECT_NE(c.reason.find("single scattering alone is within 10% of full transport"), std::string::npos) << c.reason;
}

TEST(MethodTable, AutoTakesSsForLargeImagesOfSingleScattering) {
    const MethodChoice c = chooseMethod(sceneWith(Rgb(0.1), 512));
    EXPECT_EQ(c.method, "ss") << c.reason;
}

TEST(MethodTable, AutoAddsMultipleScatteringWhereAnyChannelScattersMuch) {
    for (const Rgb& albedo : {Rgb(0.8), Rgb(0.05, 0.05, 0.9)}) {
        const MethodChoice c = chooseMethod(sceneWith(albedo, 64));
#ifdef LUCENT_HAVE_OPENCL
        EXPECT_EQ(c.method, "lbl") << c.reason;
#else
        EXPECT_EQ(c.method, "ss") << c.reason;
        EXPECT_NE(c.reason.find("cannot add it"), std::string::npos) << c.reason;
#endif
        EXPECT_NE(c.reason.find("leaves out the light scattered more than once"), std::string::npos) << c.reason;
    }
}

TEST(MethodTable, AutoFollowsForwardScatteringWithMdomOrThePathTracer) {
    // Up to g 0.8 mdom is within the goal, whatever the image's size; past
    // it, or without mdom, only the path tracer is, with many paths.
    for (int size : {64, 512}) {
        const MethodChoice c = chooseMethod(sceneWith(Rgb(0.9), size, 0.8));
#ifdef LUCENT_HAVE_OPENCL
        EXPECT_EQ(c.method, "mdom") << c.reason;
        EXPECT_NE(c.reason.find("mdom follows forward scattering"), std::string::npos) << c.reason;
#else
        EXPECT_EQ(c.method, "path") << c.reason;
        EXPECT_NE(c.reason.find("this build has no mdom"), std::string::npos) << c.reason;
#endif
        EXPECT_NE(c.reason.find("beyond what lbl's diffusion holds"), std::string::npos) << c.reason;
    }
    const MethodChoice beyond = chooseMethod(sceneWith(Rgb(0.9), 512, 0.9));
    EXPECT_EQ(beyond.method, "path") << beyond.reason;
    EXPECT_NE(beyond.reason.find("--samples 4096 --noise 0.05"), std::string::npos) << beyond.reason;
    EXPECT_NE(chooseMethod(sceneWith(Rgb(0.9), 64, 0.3)).method, "path");
}

// The bundled sphere's radius is 1: sigma_t is its optical radius.
SceneDesc refracting(const std::string& model, double albedo, double g = 0.0, double sigmaT = 2.0) {
    SceneDesc scene = sceneWith(Rgb(albedo), 512, g);
    scene.objects[0].mesh = test::sourceDir() / "models" / model;
    scene.objects[0].medium.sigmaT = Rgb(sigmaT);
    scene.objects[0].medium.ior = 1.33;
    return scene;
}

// lbl is within the goal at a refracting boundary only where the refracted view
// folds nowhere (docs/accuracy.md, What auto picks): a smooth convex surface, a
// moderate albedo, no forward scattering.
TEST(MethodTable, AutoTakesLblForARefractingSmoothConvexObject) {
    for (double albedo : {0.05, 0.8}) {
        const MethodChoice c = chooseMethod(refracting("sphere.obj", albedo));
#ifdef LUCENT_HAVE_OPENCL
        EXPECT_EQ(c.method, "lbl") << c.reason;
        EXPECT_NE(c.reason.find("ior 1.33 and a smooth convex surface"), std::string::npos) << c.reason;
#else
        EXPECT_EQ(c.method, "path") << c.reason;
#endif
    }
}

TEST(MethodTable, AutoTakesThePathTracerForRefractingFoldsOfTheView) {
    const std::pair<std::string, SceneDesc> cases[] = {
        {"sharp edges", refracting("cube.obj", 0.8)},
        {"concave parts", refracting("torus.obj", 0.8)},
        {"concave parts", refracting("bunny.off", 0.8)},
        {"albedo 0.95", refracting("sphere.obj", 0.95)},
        {"g 0.30", refracting("sphere.obj", 0.8, 0.3)},
        {"g -0.5", refracting("sphere.obj", 0.8, -0.5)},
        {"optical radius 0.5", refracting("sphere.obj", 0.8, 0.0, 0.5)},
        {"optical radius 8", refracting("sphere.obj", 0.8, 0.0, 8.0)},
    };
    for (const auto& [why, scene] : cases) {
        const MethodChoice c = chooseMethod(scene);
        EXPECT_EQ(c.method, "path") << c.reason;
        EXPECT_NE(c.reason.find("ior 1.33 and " + why), std::string::npos) << c.reason;
        EXPECT_NE(c.reason.find("only the path tracer gives full transport through it within 10%"), std::string::npos)
            << c.reason;
    }
    SceneDesc two = refracting("sphere.obj", 0.8);
    two.objects.push_back(two.objects[0]);
    EXPECT_EQ(chooseMethod(two).method, "path");
}

// ss, lbl and mdom draw the environment behind and through the objects
// (core/environment_background.h): asking for it changes nothing in the choice.
TEST(MethodTable, AutoChoosesAsBeforeWhenTheEnvironmentsBackgroundIsAskedFor) {
    SceneDesc scene = sceneWith(Rgb(0.8), 512);
    scene.environment = EnvironmentDesc{};
    const std::string without = chooseMethod(scene).method;
    EXPECT_NE(without, "path");
    scene.render.background = true;
    EXPECT_EQ(chooseMethod(scene).method, without);
}

TEST(MethodTable, AutoSaysWhatItChoseAndWhy) {
    SceneDesc scene;
    const ResolvedMethod r = resolveMethod("auto", scene);
    ASSERT_NE(r.entry, nullptr);
    EXPECT_EQ(r.entry->name, chooseMethod(scene).method);
    EXPECT_FALSE(r.reason.empty());
    EXPECT_TRUE(resolveMethod("reference", scene).reason.empty());
}

class OneSphere : public ::testing::Test {
protected:
    void SetUp() override {
        scene.file = dir.path() / "scene.json";
        ObjectDesc o = test::simpleObject(test::modelsDir() / "sphere.obj", 2.0);
        o.name = "ball";
        o.fingerprint = 7;
        o.samples = dir.path() / "ball.lsf";
        scene.objects = {o};
    }
    test::ScratchDir dir;
    SceneDesc scene;
};

TEST_F(OneSphere, SampleSetsOfAnotherObjectAreRejectedFromFilesAndFromMemory) {
    LoadedScene loaded = loadScene(scene, false);
    EXPECT_FALSE(loaded.hasSamples());
    PreprocessSettings tiny = qualityPreset("draft");
    tiny.samples = 300;
    SampleSet made = preprocessObject(loaded.objects[0], tiny);
    EXPECT_EQ(made.sceneFingerprint, 7u);
    attachSamples(loaded, {made});
    EXPECT_TRUE(loaded.hasSamples());

    SampleSet foreign = made;
    foreign.sceneFingerprint = 8;
    try {
        attachSamples(loaded, {foreign});
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_STREQ(e.what(),
                     "in-memory samples of ball: sample file was made for a different mesh or medium than "
                     "object 'ball'; run lucent preprocess again");
    }
    EXPECT_THROW(attachSamples(loaded, {}), Error);
    writeSampleFile(scene.objects[0].samples, foreign);
    try {
        loadScene(scene, true);
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()).rfind((dir.path() / "ball.lsf").string() + ": sample file was made for", 0),
                  0u);
    }
}

TEST_F(OneSphere, MethodsThatDrawFromSamplesRefuseASceneWithout) {
    const LoadedScene loaded = loadScene(scene, false);
    EXPECT_THROW(renderWith(findMethod("ss"), loaded, MethodSettings{}), Error);
}

TEST(Statistics, MedianOfOddAndEvenCounts) {
    EXPECT_EQ(median({}), 0.0);
    EXPECT_EQ(median({5.0, 1.0, 3.0}), 3.0);
    EXPECT_EQ(median({4.0, 1.0, 3.0, 2.0}), 2.5);
}

}  // namespace
}  // namespace lucent
