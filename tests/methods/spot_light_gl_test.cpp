// Spot lights in every method, against KHR_lights_punctual's falloff at chosen
// pixels of a slab lit from above. Each method renders the slab twice, under a
// point light and under a spot at the same place with the same intensity; the
// ratio of the two images is what the cone lets through.
// - Single scattering (ss, reference): the ratio at a pixel is the falloff
//   averaged along the pixel's ray with single scattering's weight
//   exp(-sigma_t (u + l)) / d^2, a one-dimensional quadrature done here from the
//   formula, independent of the renderers. Two slabs: sigma_t 20, which ss draws
//   in closed form (optically thick), and sigma_t 4, which it samples.
// - Full transport (path, lbl, mdom), on the thick slab: multiply scattered
//   light spreads a few transport lengths (here about 0.05, under a voxel of the
//   hybrids' grids), so well inside the inner cone the ratio is 1 and well
//   beyond the outer cone 0.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "core/camera_rays.h"
#include "core/loaded_scene.h"
#include "methods/method_table.h"
#include "preprocess/preprocessor.h"
#include "tests/support/test_support.h"

namespace lucent {
namespace {

constexpr double kThick = 20.0, kSampled = 4.0, kAlbedo = 0.3;  // sigma_t of the two slabs
constexpr double kTop = 0.0, kBottom = -0.6;                    // the slab's faces
const Vec3 kSpotAt(0.0, 1.5, 0.0);
constexpr double kInner = 15.0, kOuter = 35.0;  // degrees

// KHR_lights_punctual's falloff, written from its definition in angles.
double khrFalloff(double angleDegrees) {
    const double cosInner = std::cos(kInner * kPi / 180.0), cosOuter = std::cos(kOuter * kPi / 180.0);
    const double t = std::clamp((std::cos(angleDegrees * kPi / 180.0) - cosOuter) / (cosInner - cosOuter), 0.0, 1.0);
    return t * t;
}

// The single-scattering ratio along a ray that enters the slab's top at x going
// along dir, by the midpoint rule over 40 optical depths.
double singleScatteringRatio(double sigmaT, const Vec3& x, const Vec3& dir) {
    double weighted = 0.0, total = 0.0;
    const double du = 0.01 / sigmaT;
    for (double u = 0.5 * du; u < 40.0 / sigmaT; u += du) {
        const Vec3 p = x + u * dir;
        if (p.y < kBottom) break;
        const Vec3 toLight = kSpotAt - p;
        const double d = glm::length(toLight);
        const double inside = (kTop - p.y) * d / toLight.y;  // the straight way up to the top face
        const double w = std::exp(-sigmaT * (u + inside)) / (d * d);
        const double angle = std::acos(std::clamp(toLight.y / d, -1.0, 1.0)) * 180.0 / kPi;  // axis: -y
        weighted += w * khrFalloff(angle);
        total += w;
    }
    return weighted / total;
}

struct Pixel {
    int x, y;
    double expected;  // single scattering's ratio
    double angle;     // of the point where the pixel's ray enters, from the spot's axis
};

struct Slab {
    LoadedScene scene;
    std::vector<Pixel> pixels;
};

class SpotLight : public testing::Test {
protected:
    static void SetUpTestSuite() {
        dir_ = new test::ScratchDir;
        thick_ = slab(kThick);
        sampled_ = slab(kSampled);
        ASSERT_EQ(thick_->scene.samples[0].parameters.scheme, SampleScheme::OpticallyThick);
        ASSERT_NE(sampled_->scene.samples[0].parameters.scheme, SampleScheme::OpticallyThick);
    }
    static Slab* slab(double sigmaT) {
        SceneDesc scene;
        scene.file = "slab.json";
        scene.camera = test::squareCamera(Vec3(0.0, 6.0, 0.0), Vec3(0.0), 28.0, 24);
        scene.camera.up = Vec3(0.0, 0.0, -1.0);
        scene.lights = {test::pointLight(kSpotAt, Rgb(10.0))};
        const auto mesh = test::writeBox(*dir_, "slab.obj", Vec3(-1.6, kBottom, -1.6), Vec3(1.6, kTop, 1.6));
        scene.objects = {test::simpleObject(mesh, sigmaT, kAlbedo)};
        Slab* s = new Slab{loadScene(scene, false), {}};
        attachSamples(s->scene, {preprocessObject(s->scene.objects[0], qualityPreset("draft"))});
        const CameraRays rays(scene.camera);
        for (int y = 0; y < scene.camera.height; ++y)
            for (int x = 0; x < scene.camera.width; ++x) {
                const Vec3 d = rays.direction(x + 0.5, y + 0.5);
                const Vec3 hit = rays.origin() + (kTop - rays.origin().y) / d.y * d;
                const Vec3 fromSpot = glm::normalize(hit - kSpotAt);
                const double angle = std::acos(-fromSpot.y) * 180.0 / kPi;
                s->pixels.push_back({x, y, singleScatteringRatio(sigmaT, hit, d), angle});
            }
        return s;
    }
    static void TearDownTestSuite() {
        delete sampled_;
        delete thick_;
        delete dir_;
    }

    // The method's image under the spot over its image under the point light, per pixel (green).
    static std::vector<double> ratios(Slab& slab, const std::string& name,
                                      const std::map<std::string, double>& values) {
        const MethodEntry& entry = findMethod(name);
        MethodOptions options(entry.options);
        for (const auto& [option, value] : values) options.set(option, value);
        MethodSettings settings;
        settings.surface = false;
        LoadedScene& scene = slab.scene;
        scene.desc.lights[0].spot.reset();
        const Image point = renderWith(entry, *entry.create(options), scene, settings);
        scene.desc.lights[0].spot = SpotCone{Vec3(0.0, -1.0, 0.0), kInner, kOuter};
        const Image spot = renderWith(entry, *entry.create(options), scene, settings);
        std::vector<double> out;
        for (const Pixel& p : slab.pixels) {
            const double below = point.at(p.x, p.y).g;
            out.push_back(below > 0.0 ? spot.at(p.x, p.y).g / below : -1.0);
        }
        return out;
    }

    // Every pixel whose entry point lies within [lo, hi] degrees of the axis: the largest
    // difference between the method's ratio and the truth (single scattering's quadrature,
    // or 1 and 0 on the plateau and in the dark).
    static double worstIn(const Slab& slab, const std::vector<double>& ratio, double lo, double hi, bool quadrature) {
        double worst = 0.0;
        int count = 0;
        for (size_t i = 0; i < slab.pixels.size(); ++i) {
            const Pixel& p = slab.pixels[i];
            if (p.angle < lo || p.angle > hi) continue;
            const double truth = quadrature ? p.expected : (hi <= kInner ? 1.0 : 0.0);
            worst = std::max(worst, std::abs(ratio[i] - truth));
            ++count;
        }
        EXPECT_GT(count, 8) << "too few pixels in [" << lo << ", " << hi << "]";
        return worst;
    }

    static test::ScratchDir* dir_;
    static Slab *thick_, *sampled_;
};
test::ScratchDir* SpotLight::dir_ = nullptr;
Slab* SpotLight::thick_ = nullptr;
Slab* SpotLight::sampled_ = nullptr;

TEST_F(SpotLight, TheQuadratureMeetsTheFormulaWhereTheLightBarelyEntersTheSlab) {
    // The test's own truth: at the surface of the thick slab the ratio is the formula.
    for (const Pixel& p : thick_->pixels) EXPECT_NEAR(p.expected, khrFalloff(p.angle), 0.05) << p.angle;
}

TEST_F(SpotLight, ExactSingleScatteringFollowsTheConeAtEveryPixel) {
    for (Slab* slab : {thick_, sampled_})
        EXPECT_LT(worstIn(*slab, ratios(*slab, "reference", {}), 0.0, 90.0, true), 1e-3);
}

// ss's Gaussians spread each sample's light over its width: the ramp within 0.05.
TEST_F(SpotLight, SsFollowsTheConeDrawnInClosedFormAndFromItsSamples) {
    for (Slab* slab : {thick_, sampled_}) {
        const std::vector<double> r = ratios(*slab, "ss", {});
        const double plateau = worstIn(*slab, r, 0.0, kInner - 3.0, true),
                     ramp = worstIn(*slab, r, kInner, kOuter, true), dark = worstIn(*slab, r, kOuter + 3.0, 90.0, true);
        std::printf("ss (%s): plateau %.4f ramp %.4f dark %.4f\n", slab == thick_ ? "thick" : "sampled", plateau, ramp,
                    dark);
        EXPECT_LT(plateau, 0.02);
        EXPECT_LT(ramp, 0.05);
        EXPECT_LT(dark, 0.02);
    }
}

TEST_F(SpotLight, FullTransportIsLitInsideTheInnerConeAndDarkBeyondTheOuter) {
    for (const auto& [name, values] : std::vector<std::pair<std::string, std::map<std::string, double>>>{
             {"path", {{"samples", 16}}}, {"lbl", {{"grid", 40}}}, {"mdom", {{"grid", 40}, {"directions", 24}}}}) {
        const std::vector<double> r = ratios(*thick_, name, values);
        const double plateau = worstIn(*thick_, r, 0.0, kInner - 3.0, false),
                     dark = worstIn(*thick_, r, kOuter + 5.0, 90.0, false);
        std::printf("%s: plateau %.4f dark %.4f\n", name.c_str(), plateau, dark);
        EXPECT_LT(plateau, 0.03) << name;
        EXPECT_LT(dark, 0.03) << name;
    }
}

// Through a refracting boundary the cone applies where the light enters (core/refraction.h's
// solve, ss's traced light, mdom's per-voxel solve, lbl's photons): the light
// under a pixel still enters near it, so the plateau and the dark hold as before.
// ss refracts the light only where it has samples: it runs on the sampled slab.
TEST_F(SpotLight, EveryMethodFollowsTheConeThroughARefractingBoundary) {
    for (Slab* slab : {thick_, sampled_}) slab->scene.objects[0].setIor(1.5);
    for (const auto& [name, values] : std::vector<std::pair<std::string, std::map<std::string, double>>>{
             {"reference", {}},
             {"ss", {}},
             {"path", {{"samples", 16}}},
             {"lbl", {{"grid", 40}}},
             {"mdom", {{"grid", 40}, {"directions", 24}}}}) {
        Slab& slab = name == "ss" ? *sampled_ : *thick_;
        const std::vector<double> r = ratios(slab, name, values);
        const double plateau = worstIn(slab, r, 0.0, kInner - 5.0, false),
                     dark = worstIn(slab, r, kOuter + 5.0, 90.0, false);
        std::printf("%s at ior 1.5: plateau %.4f dark %.4f\n", name.c_str(), plateau, dark);
        EXPECT_LT(plateau, 0.03) << name;
        EXPECT_LT(dark, 0.03) << name;
    }
    for (Slab* slab : {thick_, sampled_}) slab->scene.objects[0].setIor(1.0);
}

}  // namespace
}  // namespace lucent
