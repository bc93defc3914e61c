// Numerical stability at the extremes (issue 4): every method renders every pixel
// finite and non-negative for vanishing and enormous extinction, albedo 0 and 1,
// tiny and huge objects, Gaussians far wider and narrower than a pixel, lights
// inside and on the object, the camera inside it, 64 lights and a single sample.
// Where the reference is defined, ss stays within the stated bounds of it.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "core/image_compare.h"
#include "preprocess/preprocessor.h"
#include "reference/reference_renderer.h"
#include "core/loaded_scene.h"
#include "runtime/ss_method.h"
#include "tests/runtime/ss_helper.h"
#include "tests/support/test_support.h"

namespace lucent {
namespace {

struct Case {
    double sigmaT = 2.0, albedo = 0.75, scale = 1.0, widthFactor = 1.5;
    std::vector<Light> lights;
    Vec3 camera{0, 0, 5};
    int samples = 1500;
    bool singleSample = false;
};

// The unit sphere scaled by c.scale (with sigma_t / scale, so that the image is
// the same), 48x48 pixels.
struct Render {
    Image ss, reference;
    SceneDesc scene;  // with its sample file written
};

Render render(const Case& c, const test::ScratchDir& dir) {
    // Scale the sphere's vertices.
    std::ifstream in(test::modelsDir() / "sphere.obj");
    std::ostringstream out;
    for (std::string line; std::getline(in, line);) {
        if (line.rfind("v ", 0) == 0) {
            std::istringstream v(line.substr(2));
            double x, y, z;
            v >> x >> y >> z;
            out << "v " << x * c.scale << ' ' << y * c.scale << ' ' << z * c.scale << '\n';
        } else {
            out << line << '\n';
        }
    }
    const auto mesh = dir.write("sphere.obj", out.str());
    SceneDesc scene;
    const bool outside = c.camera.z > 1.0;
    scene.camera =
        test::squareCamera(c.camera * c.scale, Vec3(0, 0, outside ? 0.0 : -1.0) * c.scale, outside ? 30 : 60, 48);
    for (Light l : c.lights) {
        if (l.type == Light::Type::Point) {
            l.position *= c.scale;
            l.power *= c.scale * c.scale;  // the same irradiance at the scaled distance
        }
        scene.lights.push_back(l);
    }
    ObjectDesc o = test::simpleObject(mesh, c.sigmaT / c.scale, c.albedo);
    o.samples = dir.path() / "sphere.lsf";
    scene.objects = {o};
    std::vector<std::string> warnings;
    const std::vector<VolumeObject> objects = loadObjects(scene, warnings);
    PreprocessSettings settings = qualityPreset("draft");
    settings.samples = c.samples;
    settings.widthFactor = c.widthFactor;
    SampleSet set = preprocessObject(objects[0], settings);
    if (c.singleSample) {
        set.positions.resize(1), set.radii.resize(1), set.widths.resize(1), set.weights.resize(1);
        set.extinction.resize(1), set.region.resize(1), set.image.resize(1), set.boundary.resize(1),
            set.truncationError.resize(1);
        set.sh.resize(set.coefficientsPerSample());
    }
    writeSampleFile(o.samples, set);
    Render r;
    r.ss = test::renderSs(scene, false);
    ReferenceSettings reference;
    reference.surface = false;
    reference.tolerance = 1e-3;
    r.reference = ReferenceRenderer(scene, objects).render(reference);
    r.scene = scene;
    return r;
}

Light pointLight(const Vec3& p, double intensity = 40.0) { return test::pointLight(p, Rgb(intensity)); }

void expectFiniteAndNonNegative(const Image& image, const char* what) {
    size_t bad = 0;
    for (const auto& p : image.pixels)
        for (int k = 0; k < 3; ++k) bad += !(std::isfinite(p[k]) && p[k] >= 0.0f);
    EXPECT_EQ(bad, 0u) << what;
}

double meanOf(const Image& image) {
    double sum = 0.0;
    for (const auto& p : image.pixels) sum += p.g;
    return sum / double(image.pixels.size());
}

// The mean ratio ss / reference, after checking both images.
double checkedRatio(const Case& c) {
    test::ScratchDir dir;
    const Render r = render(c, dir);
    expectFiniteAndNonNegative(r.ss, "ss");
    expectFiniteAndNonNegative(r.reference, "reference");
    const double ref = meanOf(r.reference);
    const double ratio = ref > 0.0 ? meanOf(r.ss) / ref : (meanOf(r.ss) == 0.0 ? 1.0 : kInfinity);
    std::printf("ss / reference %.3f, relative RMSE %.3f\n", ratio, compareImages(r.ss, r.reference).relativeRmse);
    return ratio;
}

Case sphere(double sigmaT) {
    Case c;
    c.sigmaT = sigmaT;
    c.lights = {pointLight(Vec3(3, 3, 3))};
    return c;
}

TEST(Extremes, VanishingExtinction) {
    // 1500 samples: the bounds are those of that count (docs/accuracy.md), wider than at the default.
    EXPECT_NEAR(checkedRatio(sphere(1e-6)), 1.0, 0.05);  // the goal of optical radii under 0.5
}

TEST(Extremes, EnormousExtinction) {
    // Light dies within 0.05 and 5e-4 of the surface, far inside one Gaussian:
    // the preprocessor makes the sphere a skin (SampleScheme::OpticallyThick), whose closed
    // form is exact under a plane; the sphere's curvature costs a few per cent.
    for (double sigmaT : {1e2, 1e4}) {
        test::ScratchDir dir;
        const Render r = render(sphere(sigmaT), dir);
        expectFiniteAndNonNegative(r.ss, "ss");
        const ImageError e = compareImages(r.ss, r.reference);
        std::printf("sigma_t %g: relative RMSE %.3f, mean ratio %.3f\n", sigmaT, e.relativeRmse, e.meanRatio);
        EXPECT_LT(e.relativeRmse, 0.05) << sigmaT;
        EXPECT_NEAR(e.meanRatio, 1.0, 0.03) << sigmaT;
    }
}

TEST(Extremes, AlbedoZeroScattersNothingAndAlbedoOneStaysFinite) {
    Case black = sphere(2.0);
    black.albedo = 0.0;
    EXPECT_EQ(checkedRatio(black), 1.0);  // both images exactly black
    Case white = sphere(2.0);
    white.albedo = 1.0;
    EXPECT_NEAR(checkedRatio(white), 1.0, 0.1);
}

TEST(Extremes, TinyAndHugeObjectsGiveTheSameImage) {
    test::ScratchDir unitDir, tinyDir, hugeDir;
    const Render unit = render(sphere(2.0), unitDir);
    const double unitError = compareImages(unit.ss, unit.reference).relativeRmse;
    for (double scale : {1e-3, 1e3}) {
        Case c = sphere(2.0);
        c.scale = scale;
        const Render scaled = render(c, scale < 1 ? tinyDir : hugeDir);
        expectFiniteAndNonNegative(scaled.ss, "scaled");
        // The physics is scale-free: the reference must not move.
        EXPECT_LT(compareImages(scaled.reference, unit.reference).relativeRmse, 0.01) << "scale " << scale;
        // Preprocessing is scale-free (preprocess/distance_field.h: the grid in the
        // object's own frame), so ss gives the same image up to single precision.
        const double error = compareImages(scaled.ss, scaled.reference).relativeRmse;
        const double difference = compareImages(scaled.ss, unit.ss).relativeRmse;
        std::printf("scale %g: relative RMSE %.3f (unit sphere %.3f), against the unit sphere's ss %.2e\n", scale,
                    error, unitError, difference);
        EXPECT_LT(difference, 1e-3) << "scale " << scale;
    }
}

// Outside the measured range of widths, and with a light inside the object or at
// its surface, ss misses its goal (measured 0.88 and 0.12 of the light at width
// factors 0.05 and 20, 0.34 and 1.23 with the light at the centre and at the
// surface). No bound here accepts that: the images must stay finite and
// non-negative, and --method ss must say, before rendering, that it is off.
bool ssWarns(const Case& c, const std::string& words) {
    test::ScratchDir dir;
    const Render r = render(c, dir);
    expectFiniteAndNonNegative(r.ss, "ss");
    expectFiniteAndNonNegative(r.reference, "reference");
    const LoadedScene loaded = loadScene(r.scene, true);
    for (const std::string& line : SsMethod().limitations(loaded, MethodSettings{}))
        if (line.find(words) != std::string::npos) return true;
    return false;
}

TEST(Extremes, GaussiansFarWiderAndNarrowerThanTheirSpacingAreWarnedAbout) {
    for (double factor : {0.05, 20.0}) {
        Case c = sphere(2.0);
        c.widthFactor = factor;
        EXPECT_TRUE(ssWarns(c, "far outside the measured 1 to 2.5")) << factor;
    }
    EXPECT_FALSE(ssWarns(sphere(2.0), "far outside"));  // the default width: no warning
}

TEST(Extremes, LightInsideOrAtTheSurfaceIsWarnedAbout) {
    for (const Vec3& p : {Vec3(0, 0, 0), Vec3(0, 0.999, 0)}) {
        Case c = sphere(2.0);
        c.lights = {pointLight(p, 1.0)};
        EXPECT_TRUE(ssWarns(c, "light 0 lies")) << p.y;
    }
    EXPECT_FALSE(ssWarns(sphere(2.0), "light 0 lies"));  // a light outside: no warning
}

// A peaked phase function sees an environment's directions one by one (docs/accuracy.md, Environment lights).
TEST(Extremes, AnEnvironmentInAStronglyPeakedMediumIsWarnedAbout) {
    SceneDesc desc;
    desc.camera = test::squareCamera(Vec3(0.0, 0.0, 5.0), Vec3(0.0), 30.0, 32);
    desc.objects = {test::simpleObject(test::modelsDir() / "sphere.obj", 2.0, 0.8)};
    Image sky(8, 4);
    for (auto& p : sky.pixels) p = glm::vec3(1.0f);
    auto warned = [&](double g, bool environment) {
        desc.objects[0].medium.g = g;
        LoadedScene scene = loadScene(desc, false);
        if (environment) scene.environment = std::make_shared<EnvironmentMap>(sky, 1.0, glm::dmat3(1.0));
        for (const std::string& line : SsMethod::sampleLimitations(scene, SsOptions{}))
            if (line.find("a peaked phase function sees one by one") != std::string::npos) return true;
        return false;
    };
    EXPECT_TRUE(warned(-0.5, true));
    EXPECT_TRUE(warned(0.9, true));
    EXPECT_FALSE(warned(0.3, true));
    EXPECT_FALSE(warned(0.9, false));  // point lights: the phase function is exact
}

// An optically thick object whose seen surface is lit at grazing incidence
// (runtime/grazing_light.h); lit from beside or behind, none of it lit, the
// light across the edges is drawn (tests/runtime/optically_thick_gl_test.cpp).
TEST(Extremes, AnOpticallyThickCubeLitAtGrazingIncidenceIsWarnedAbout) {
    SceneDesc desc;
    desc.camera = test::squareCamera(Vec3(0.0, 1.2, 5.0), Vec3(0.0), 40.0, 64);
    desc.objects = {test::simpleObject(test::modelsDir() / "cube.obj", 80.0, 0.9)};
    LoadedScene scene = loadScene(desc, false);
    attachSamples(scene, {preprocessObject(scene.objects[0], qualityPreset("draft"))});
    ASSERT_EQ(scene.samples[0].parameters.scheme, SampleScheme::OpticallyThick);
    auto warned = [&](double degrees) {
        const double a = degrees * kPi / 180.0;
        scene.desc.lights = {test::pointLight(Vec3(4.0 * std::sin(a), -0.3, 4.0 * std::cos(a)), Rgb(60.0))};
        for (const std::string& line : SsMethod::sampleLimitations(scene, SsOptions{}))
            if (line.find("optically thick and its seen surface is lit at grazing") != std::string::npos) return true;
        return false;
    };
    // docs/results/grazing.md: 0.0%, 8.1%, 58%, 0.1% and 0.8% from the reference.
    EXPECT_FALSE(warned(0.0));    // in front
    EXPECT_FALSE(warned(74.0));   // the seen surface lit at 0.026
    EXPECT_TRUE(warned(75.0));    // at 0.009
    EXPECT_FALSE(warned(90.0));   // beside: none of it lit, the edges' light drawn
    EXPECT_FALSE(warned(135.0));  // behind
}

TEST(Extremes, CameraInsideTheObject) {
    Case c = sphere(0.5);
    c.camera = Vec3(0, 0, 0.5);
    // The rays start at the eye and are attenuated from there (measured 0.956).
    EXPECT_NEAR(checkedRatio(c), 1.0, 0.1);
}

TEST(Extremes, SixtyFourLights) {
    Case c = sphere(2.0);
    for (int k = 0; k < 64; ++k) {
        const double a = 2.0 * kPi * k / 64.0;
        c.lights.push_back(pointLight(Vec3(3 * std::cos(a), 1.0, 3 * std::sin(a)), 1.0));
    }
    EXPECT_NEAR(checkedRatio(c), 1.0, 0.1);
}

TEST(Extremes, OneSample) {
    Case c = sphere(2.0);
    c.singleSample = true;
    test::ScratchDir dir;
    const Render r = render(c, dir);
    expectFiniteAndNonNegative(r.ss, "ss");
    EXPECT_GT(meanOf(r.ss), 0.0);
}

}  // namespace
}  // namespace lucent
