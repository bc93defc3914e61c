// --method ss against --method reference (the ground truth validated against
// closed forms in tests/reference), the two offscreen backends against each
// other, and the runtime's errors.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>

#include "core/error.h"
#include "core/image_compare.h"
#include "core/loaded_scene.h"
#include "core/sample_set.h"
#include "preprocess/preprocessor.h"
#include "reference/reference_renderer.h"
#include "runtime/internal/gl_program.h"
#include "runtime/offscreen_context.h"
#include "runtime/ss_method.h"
#include "tests/runtime/ss_goal.h"
#include "tests/runtime/ss_helper.h"
#include "tests/support/test_support.h"

namespace lucent {
namespace {

// The homogeneous sphere of issue 3: sigma_t 2, albedo 0.75, point light at
// (3, 3, 3), camera at (0, 0, 5).
struct SphereScene {
    explicit SphereScene(const test::ScratchDir& dir, int size = 128) {
        scene.camera = test::squareCamera(Vec3(0, 0, 5), Vec3(0), 30, size);
        scene.lights = {test::pointLight(Vec3(3, 3, 3), Rgb(40.0))};
        ObjectDesc o = test::simpleObject(test::modelsDir() / "sphere.obj", 2.0, 0.75);
        o.samples = dir.path() / "sphere.lsf";
        o.fingerprint = 42;
        scene.objects = {o};
        std::vector<std::string> warnings;
        objects = loadObjects(scene, warnings);
    }
    void preprocess(const PreprocessSettings& settings) const {
        SampleSet s = preprocessObject(objects[0], settings);
        s.sceneFingerprint = 42;
        writeSampleFile(scene.objects[0].samples, s);
    }
    // The draft preset with this many samples: the quick sphere of the tests
    // that compare two ways of drawing it, not its accuracy.
    void preprocessDraft(int samples) const {
        PreprocessSettings settings = qualityPreset("draft");
        settings.samples = samples;
        preprocess(settings);
    }
    Image reference() const {
        ReferenceSettings settings;
        settings.tolerance = 1e-4;
        return ReferenceRenderer(scene, objects).render(settings);
    }
    Image ss(const std::string& backend = "") const { return test::renderSs(scene, true, backend); }
    SceneDesc scene;
    std::vector<VolumeObject> objects;
};

TEST(SingleScattering, DefaultQualitySphereMeetsItsGoal) {
    test::ScratchDir dir;
    SphereScene sphere(dir, 256);
    sphere.preprocess(qualityPreset("default"));
    const ImageError all = compareImages(sphere.ss(), sphere.reference());
    const ImageError interior = compareImages(sphere.ss(), sphere.reference(), 3);
    std::printf(
        "sphere, default quality: relative RMSE %.4f, MARE %.4f, mean ratio %.4f; 3 px from the silhouette: "
        "%.4f, %.4f\n",
        all.relativeRmse, all.meanAbsoluteRelativeError, all.meanRatio, interior.relativeRmse,
        interior.meanAbsoluteRelativeError);
    // The goal (sigma_t 2: 10%), over the whole silhouette and inside it.
    const double goal = test::ssGoalRelativeRmse(sphere.objects);
    ASSERT_EQ(goal, 0.10);
    EXPECT_LT(all.relativeRmse, goal);
    EXPECT_LT(interior.relativeRmse, goal);
}

// Through a refracting boundary (runtime/internal/refracted_view.h) against
// the reference, which follows both of Fresnel's branches and finds the light
// through the boundary (tests/reference/refraction_test.cpp holds it to the
// half-space's closed form and to the path tracer). Issue 41's goal for ss
// against single scattering with refraction: 10%, at the two indices.
TEST(SingleScattering, RefractingSphereMeetsItsGoal) {
    test::ScratchDir dir;
    SphereScene sphere(dir, 64);
    sphere.preprocess(qualityPreset("default"));  // the samples do not depend on the ior
    for (double ior : {1.33, 1.5}) {
        sphere.scene.objects[0].medium.ior = ior;
        std::vector<std::string> warnings;
        sphere.objects = loadObjects(sphere.scene, warnings);
        ReferenceSettings settings;
        settings.tolerance = 1e-3;
        const Image reference = ReferenceRenderer(sphere.scene, sphere.objects).render(settings);
        const ImageError e = compareImages(sphere.ss(), reference);
        std::printf("sphere at ior %.2f: relative RMSE %.4f, mean ratio %.4f\n", ior, e.relativeRmse, e.meanRatio);
        EXPECT_LT(e.relativeRmse, 0.10) << "ior " << ior;
    }
}

// Seen across an edge, a refracting box shows each point inside through two
// faces, and ss draws it where one pixel's refracted ray passes nearest: the
// warning says so before it renders, and what it says holds (the box misses the
// goal of 10%, the sphere above meets it and is told so).
TEST(SingleScattering, ARefractingBoxIsWarnedThatItsFacesFoldTheView) {
    test::ScratchDir dir;
    SceneDesc scene;
    scene.camera = test::squareCamera(Vec3(2.2, 1.9, 4.2), Vec3(0), 30, 48);
    scene.lights = {test::pointLight(Vec3(3, 3, 3), Rgb(40.0))};
    ObjectDesc box = test::simpleObject(test::writeBox(dir, "box.obj", Vec3(-1.0), Vec3(1.0)), 2.0, 0.8);
    box.medium.ior = 1.5;
    box.samples = dir.path() / "box.lsf";
    scene.objects = {box};
    std::vector<std::string> warnings;
    const auto objects = loadObjects(scene, warnings);
    PreprocessSettings draft = qualityPreset("default");
    draft.samples = 20000;
    writeSampleFile(box.samples, preprocessObject(objects[0], draft));
    const auto says = [](const SceneDesc& s, const std::string& what) {
        for (const std::string& line : SsMethod::boundaryLimitations(loadScene(s, true), SsOptions{}))
            if (line.find(what) != std::string::npos) return true;
        return false;
    };
    EXPECT_TRUE(says(scene, "where its sharp edges may show it twice"));
    ReferenceSettings settings;
    settings.surface = false;
    const ImageError e =
        compareImages(test::renderSs(scene, false), ReferenceRenderer(scene, objects).render(settings));
    std::printf("refracting box: relative RMSE %.4f, mean ratio %.4f\n", e.relativeRmse, e.meanRatio);
    EXPECT_GT(e.relativeRmse, 0.10);
    EXPECT_LT(e.meanRatio, 1.0);  // too dark, as the warning says

    // Too few samples to hold its light: optically thick, marched index-matched,
    // and told how far off that is (docs/results/refraction-shapes.md).
    PreprocessSettings thick = qualityPreset("draft");
    thick.samples = 10;
    writeSampleFile(box.samples, preprocessObject(objects[0], thick));
    EXPECT_TRUE(says(scene, "is drawn index-matched (optically thick, each pixel's ray marched)"));
    EXPECT_TRUE(says(scene, "2.2-4.7x too bright"));

    SphereScene sphere(dir, 16);
    sphere.scene.objects[0].medium.ior = 1.5;
    sphere.preprocessDraft(2000);
    EXPECT_TRUE(says(sphere.scene, "smooth and convex, as this surface is"));
    EXPECT_FALSE(says(sphere.scene, "may show it twice"));
}

// With the surface on, the reference shades with the runtime's interpolated
// normals (core/triangle_mesh.h), so it stays the truth: the surface term alone
// (image with the surface minus image without) is the same Phong formula with
// the same normals in both, and agrees to what single precision and the
// rasteriser's interpolation leave. With flat face normals in the reference,
// the sphere's facets put the two terms 12% apart.
TEST(SingleScattering, SurfaceTermIsTheReferencesWithTheSameNormals) {
    test::ScratchDir dir;
    SphereScene sphere(dir, 96);
    SurfaceDesc surface;
    surface.diffuse = Rgb(0.3);
    surface.specular = Rgb(0.2);
    surface.shininess = 32.0;
    sphere.scene.objects[0].surface = surface;
    std::vector<std::string> warnings;
    sphere.objects = loadObjects(sphere.scene, warnings);
    sphere.preprocess(qualityPreset("draft"));
    ReferenceSettings settings;
    settings.tolerance = 1e-4;
    const ReferenceRenderer reference(sphere.scene, sphere.objects);
    const Image withSurface = reference.render(settings);
    settings.surface = false;
    const Image withoutSurface = reference.render(settings);
    const Image ssWith = test::renderSs(sphere.scene, true), ssWithout = test::renderSs(sphere.scene, false);
    Image referenceSurface = withSurface, ssSurface = ssWith;
    for (size_t i = 0; i < withSurface.pixels.size(); ++i) {
        referenceSurface.pixels[i] = withSurface.pixels[i] - withoutSurface.pixels[i];
        ssSurface.pixels[i] = ssWith.pixels[i] - ssWithout.pixels[i];
    }
    const ImageError term = compareImages(ssSurface, referenceSurface, 1);
    const ImageError all = compareImages(ssWith, withSurface);
    std::printf("surface term: relative RMSE %.2e (1 px inside the silhouette); whole image: %.4f\n", term.relativeRmse,
                all.relativeRmse);
    EXPECT_GT(term.pixels, 2000u);
    EXPECT_LT(term.relativeRmse, 1e-3);  // measured 9.4e-6
    EXPECT_LT(all.relativeRmse, test::ssGoalRelativeRmse(sphere.objects));
}

// The surface term is drawn deferred (runtime/internal/surface_pass.h): each
// pixel keeps its nearest face and that object's material. Two spheres with
// different surfaces, the nearer hiding part of the farther, against the
// reference's surface term, as above.
TEST(SingleScattering, SurfaceTermOfTwoObjectsIsEachOnesOwn) {
    test::ScratchDir dir;
    SceneDesc scene;
    scene.camera = test::squareCamera(Vec3(0, 0, 6), Vec3(0), 40, 128);
    scene.lights = {test::pointLight(Vec3(3, 3, 4), Rgb(60.0)), test::pointLight(Vec3(-4, 1, 2), Rgb(20.0))};
    for (int k = 0; k < 2; ++k) {
        ObjectDesc o = test::simpleObject(test::modelsDir() / "sphere.obj", 2.0, 0.75);
        o.name = "sphere" + std::to_string(k);
        o.samples = dir.path() / (o.name + ".lsf");
        o.fingerprint = 42 + uint64_t(k);
        o.transform =
            makeSimilarity(0.8, Vec3(0.0, 0.0, 1.0), 0.0, k == 0 ? Vec3(-0.5, 0.0, 1.0) : Vec3(0.6, 0.2, -0.5));
        SurfaceDesc surface;
        surface.diffuse = k == 0 ? Rgb(0.5, 0.1, 0.1) : Rgb(0.05, 0.2, 0.4);
        surface.specular = k == 0 ? Rgb(0.05) : Rgb(0.3);
        surface.shininess = k == 0 ? 8.0 : 64.0;
        o.surface = surface;
        scene.objects.push_back(o);
    }
    std::vector<std::string> warnings;
    const std::vector<VolumeObject> objects = loadObjects(scene, warnings);
    for (size_t k = 0; k < objects.size(); ++k) {
        SampleSet s = preprocessObject(objects[k], qualityPreset("draft"));
        s.sceneFingerprint = scene.objects[k].fingerprint;
        writeSampleFile(scene.objects[k].samples, s);
    }
    ReferenceSettings settings;
    settings.tolerance = 1e-4;
    const ReferenceRenderer reference(scene, objects);
    const Image withSurface = reference.render(settings);
    settings.surface = false;
    const Image withoutSurface = reference.render(settings);
    const Image ssWith = test::renderSs(scene, true), ssWithout = test::renderSs(scene, false);
    Image referenceSurface = withSurface, ssSurface = ssWith;
    for (size_t i = 0; i < withSurface.pixels.size(); ++i) {
        referenceSurface.pixels[i] = withSurface.pixels[i] - withoutSurface.pixels[i];
        ssSurface.pixels[i] = ssWith.pixels[i] - ssWithout.pixels[i];
    }
    const ImageError term = compareImages(ssSurface, referenceSurface, 1);
    std::printf("two objects' surface terms: relative RMSE %.2e over %zu pixels\n", term.relativeRmse, term.pixels);
    EXPECT_GT(term.pixels, 2000u);
    EXPECT_LT(term.relativeRmse, 1e-3);  // the one-object test's bound
}

TEST(SingleScattering, ErrorFallsWithSamplesAndShOrder) {
    test::ScratchDir dir;
    SphereScene sphere(dir);
    const Image reference = sphere.reference();
    auto errorWith = [&](int samples, int directions, int order) {
        PreprocessSettings s;
        s.samples = samples;
        s.projectionDirections = directions;
        s.shOrder = order;
        sphere.preprocess(s);
        return compareImages(sphere.ss(), reference).relativeRmse;
    };
    const double base = errorWith(5000, 256, 5);
    EXPECT_LT(errorWith(20000, 256, 5), 0.9 * base) << "samples";
    // On a sphere each sample's boundary ball is nearly exact, so the image barely
    // depends on the SH order (measured 6.6% at order 1, 6.4% at order 5); what the
    // order buys shows in the part of exp(-tau) that ball and SH leave out.
    auto missedWith = [&](int order) {
        PreprocessSettings s;
        s.samples = 5000;
        s.shOrder = order;
        sphere.preprocess(s);
        const SampleSet set = readSampleFile(sphere.scene.objects[0].samples);
        double sum = 0.0;
        for (float e : set.truncationError) sum += e;
        return sum / double(set.size());
    };
    const double missed2 = missedWith(2), missed5 = missedWith(5);
    EXPECT_LT(missed5, 0.5 * missed2) << "SH order";
    EXPECT_LT(base, errorWith(5000, 256, 1) + 0.002) << "SH order 1 is no better";
}

// Two objects in one scene: each with its own samples, and each shadowing the
// other's light (the reference attenuates through every object). Held to the
// goal of the sphere at sigma_t 2 (tests/runtime/ss_goal.h: relative RMSE <= 10%),
// lit from between them and through one onto the other: traced light crosses
// both. The SH hold only an object's own attenuation, so --light sh misses the
// goal there (24% measured) and says so before rendering.
TEST(SingleScattering, TwoObjectsInOneSceneMeetTheSpheresGoal) {
    test::ScratchDir dir;
    // The unit sphere moved 2.5 along x.
    std::ifstream in(test::modelsDir() / "sphere.obj");
    std::string shifted, line;
    while (std::getline(in, line)) {
        if (line.rfind("v ", 0) == 0) {
            double x, y, z;
            std::sscanf(line.c_str() + 2, "%lf %lf %lf", &x, &y, &z);
            char text[96];
            std::snprintf(text, sizeof text, "v %.17g %.17g %.17g", x + 2.5, y, z);
            line = text;
        }
        shifted += line + "\n";
    }
    SceneDesc scene;
    scene.file = dir.path() / "scene.json";
    scene.camera.position = Vec3(1.25, 0.5, 7.0);
    scene.camera.target = Vec3(1.25, 0.0, 0.0);
    scene.camera.width = scene.camera.height = 64;
    // Between and above: neither sphere shadows the other.
    scene.lights = {test::pointLight(Vec3(1.25, 4.0, 3.0), Rgb(40.0))};
    ObjectDesc left = test::simpleObject(test::modelsDir() / "sphere.obj", 2.0, 0.75);
    ObjectDesc right = test::simpleObject(dir.write("right.obj", shifted), 2.0, 0.75);
    left.name = "left", right.name = "right";
    left.fingerprint = 1, right.fingerprint = 2;
    left.samples = dir.path() / "left.lsf", right.samples = dir.path() / "right.lsf";
    scene.objects = {left, right};
    std::vector<std::string> warnings;
    const std::vector<VolumeObject> objects = loadObjects(scene, warnings);
    PreprocessSettings settings = qualityPreset("default");
    settings.samples = 10000;
    for (const VolumeObject& o : objects) writeSampleFile(o.desc().samples, preprocessObject(o, settings));
    ReferenceSettings reference;
    reference.surface = false;
    const double goal = test::ssGoalRelativeRmse(objects);
    const SsOptions sh{false, ""};
    for (const Vec3& at : {Vec3(1.25, 4.0, 3.0), Vec3(5.0, 0.3, 0.2)}) {
        scene.lights[0].position = at;
        const bool between = at.x > 2.5;
        const Image exact = ReferenceRenderer(scene, objects).render(reference);
        const ImageError traced = compareImages(test::renderSs(scene, false), exact);
        const ImageError fromSh = compareImages(test::renderSs(scene, false, "", false), exact);
        std::printf("two spheres, light at x %.2f: relative RMSE traced %.4f, sh %.4f\n", at.x, traced.relativeRmse,
                    fromSh.relativeRmse);
        EXPECT_GT(traced.pixels, 800u);
        EXPECT_LT(traced.relativeRmse, goal) << "light at x " << at.x;
        EXPECT_TRUE(SsMethod().limitations(loadScene(scene, false), MethodSettings{}).empty());
        const std::vector<std::string> said = SsMethod(sh).limitations(loadScene(scene, false), MethodSettings{});
        if (!between) {
            EXPECT_LT(fromSh.relativeRmse, goal) << "neither shadows the other";
            EXPECT_TRUE(said.empty());
            continue;
        }
        // Through the right sphere onto the left: the scene does test the shadow.
        EXPECT_GT(fromSh.relativeRmse, goal) << "the SH cannot dim one object's light by another";
        ASSERT_EQ(said.size(), 1u);
        EXPECT_NE(said[0].find("object 'right' may lie between light 0 and object 'left'"), std::string::npos)
            << said[0];
    }
}

TEST(SingleScattering, OsmesaAndEglGiveTheSameImage) {
    test::ScratchDir dir;
    SphereScene sphere(dir, 64);
    sphere.preprocessDraft(2000);
    const Image a = sphere.ss("osmesa"), b = sphere.ss("egl");
    float peak = 0.0f, worst = 0.0f;
    for (size_t i = 0; i < a.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            peak = std::max(peak, a.pixels[i][c]);
            worst = std::max(worst, std::abs(a.pixels[i][c] - b.pixels[i][c]));
        }
    EXPECT_GT(peak, 0.0f);
    EXPECT_LE(worst, 1e-5f * peak);
}

TEST(SingleScattering, APreparedContextDrawsTheSameImage) {
    // Method::prepare makes the context, frame and programs in another thread,
    // and render takes the context over; a prepare for another image size is
    // dropped. Each must draw what a render without prepare draws, to the bit:
    // the same programs run on the same data.
    test::ScratchDir dir;
    SphereScene sphere(dir, 64);
    sphere.preprocessDraft(2000);
    const LoadedScene loaded = loadScene(sphere.scene, true);
    for (const std::string backend : {"egl", "osmesa"}) {
        SCOPED_TRACE(backend);
        const MethodSettings settings;
        const SsOptions options{true, backend};
        const Image plain = SsMethod(options).render(loaded, settings);
        SsMethod prepared(options);
        prepared.prepare(sphere.scene, settings);
        const Image fromPrepared = prepared.render(loaded, settings);
        SceneDesc otherSize = sphere.scene;
        otherSize.camera.width = 32;
        SsMethod dropped(options);
        dropped.prepare(otherSize, settings);
        const Image fromDropped = dropped.render(loaded, settings);
        double peak = 0.0;
        for (const glm::vec3& p : plain.pixels) peak = std::max(peak, double(p.r));
        EXPECT_GT(peak, 0.0);
        ASSERT_EQ(fromPrepared.pixels.size(), plain.pixels.size());
        ASSERT_EQ(fromDropped.pixels.size(), plain.pixels.size());
        for (size_t i = 0; i < plain.pixels.size(); ++i) {
            ASSERT_EQ(fromPrepared.pixels[i], plain.pixels[i]) << "pixel " << i;
            ASSERT_EQ(fromDropped.pixels[i], plain.pixels[i]) << "pixel " << i;
        }
    }
}

TEST(SingleScattering, CachedReceivedLightMatchesThePerFrameComputation) {
    // g = 0 caches the received light between light changes; any g != 0 computes it
    // every frame in the vertex shader. At g = 1e-7 the two must agree.
    test::ScratchDir dir;
    SphereScene sphere(dir, 64);
    sphere.preprocessDraft(2000);
    const Image cached = sphere.ss();
    sphere.scene.objects[0].medium.g = 1e-7;
    std::vector<std::string> warnings;
    sphere.objects = loadObjects(sphere.scene, warnings);
    const Image perFrame = sphere.ss();
    const ImageError e = compareImages(cached, perFrame);
    EXPECT_GT(e.pixels, 500u);
    EXPECT_LT(e.relativeRmse, 1e-4);
}

TEST(SingleScattering, RejectsASampleFileOfAnotherObject) {
    test::ScratchDir dir;
    SphereScene sphere(dir, 16);
    PreprocessSettings s = qualityPreset("draft");
    s.samples = 500;
    SampleSet set = preprocessObject(sphere.objects[0], s);
    set.sceneFingerprint = 7;  // made for something else
    writeSampleFile(sphere.scene.objects[0].samples, set);
    try {
        sphere.ss();
        FAIL();
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("made for a different mesh or medium"), std::string::npos) << e.what();
    }
}

TEST(SingleScattering, ShaderCompileErrorsShowTheGlslLog) {
    const auto context = OffscreenContext::create(GlBackend::Auto);
    try {
        GlProgram broken{{GL_FRAGMENT_SHADER, "broken.frag", "#version 450 core\nvoid main() { undefined(); }\n"}};
        FAIL();
    } catch (const Error& e) {
        const std::string message = e.what();
        EXPECT_EQ(message.rfind("broken.frag: GLSL compile error: ", 0), 0u) << message;
        EXPECT_NE(message.find("undefined"), std::string::npos) << message;
        EXPECT_EQ(message.find('\n'), std::string::npos);
    }
}

}  // namespace
}  // namespace lucent
