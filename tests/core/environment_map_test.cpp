// The environment map: its convention (issue 42's, docs/scene-file.md), its
// sampling against the integral over texels computed here from their solid
// angles, and hostile map files.
#include <ImfOutputFile.h>
#include <ImfRgbaFile.h>
#include <gtest/gtest.h>
#include <stb_image_write.h>

#include <cmath>
#include <limits>

#include "core/environment_map.h"
#include "core/error.h"
#include "core/rng.h"
#include "core/scene.h"
#include "tests/support/test_support.h"

namespace lucent {
namespace {

// The direction of the texel centre (x, y) by the convention's formula, written out again.
Vec3 conventionDirection(int x, int y, int width, int height) {
    const double t = kPi * (y + 0.5) / height, p = 2.0 * kPi * (x + 0.5) / width;
    return {std::sin(t) * std::cos(p), std::cos(t), -std::sin(t) * std::sin(p)};
}

Image skyWithSun(int width, int height) {
    Image image(width, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            image.at(x, y) = y < height / 2 ? glm::vec3(0.3f, 0.45f, 0.8f) : glm::vec3(0.15f, 0.12f, 0.1f);
    image.at(width / 8, height / 3) = glm::vec3(4000.0f, 3800.0f, 3400.0f);
    return image;
}

// The integral of L over the sphere, texel by texel: each spans 2 pi / width in
// phi and [pi y / height, pi (y + 1) / height] in theta.
Rgb integralOverTexels(const Image& image) {
    Rgb sum(0.0);
    for (int y = 0; y < image.height; ++y) {
        const double solidAngle =
            2.0 * kPi / image.width * (std::cos(kPi * y / image.height) - std::cos(kPi * (y + 1) / image.height));
        for (int x = 0; x < image.width; ++x) sum += solidAngle * Rgb(image.at(x, y));
    }
    return sum;
}

TEST(EnvironmentMap, EachTexelArrivesFromTheDirectionTheConventionGivesIt) {
    const int width = 16, height = 8;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            Image image(width, height);
            image.at(x, y) = glm::vec3(1.0f);
            const EnvironmentMap map(image, 2.0, glm::dmat3(1.0));
            EXPECT_EQ(map.radiance(conventionDirection(x, y, width, height)), Rgb(2.0)) << x << " " << y;
        }
    // u = 0 looks towards +x, and u = 1/4 towards -z; row 0 is the top.
    Image image(4, 2);
    image.at(0, 0) = glm::vec3(1.0f, 0.0f, 0.0f);
    image.at(1, 1) = glm::vec3(0.0f, 1.0f, 0.0f);
    const EnvironmentMap map(image, 1.0, glm::dmat3(1.0));
    EXPECT_EQ(map.radiance(glm::normalize(Vec3(1.0, 0.2, -0.05))), Rgb(1.0, 0.0, 0.0));
    EXPECT_EQ(map.radiance(glm::normalize(Vec3(-0.3, -0.2, -1.0))), Rgb(0.0, 1.0, 0.0));
}

TEST(EnvironmentMap, RotationTurnsTheMapsDirectionsIntoTheWorlds) {
    Image image(16, 8);
    image.at(0, 4) = glm::vec3(1.0f);  // just below the horizon, towards +x
    EnvironmentDesc desc;
    desc.rotation = makeSimilarity(1.0, Vec3(0.0, 1.0, 0.0), 90.0, Vec3(0.0)).rotation;
    const EnvironmentMap map(image, 1.0, desc.rotation);
    // +x turned a quarter about +y (right-handed) is -z.
    const Vec3 d = conventionDirection(0, 4, 16, 8);
    EXPECT_EQ(map.radiance(desc.rotation * d), Rgb(1.0));
    EXPECT_EQ(map.radiance(d), Rgb(0.0));
    EXPECT_NEAR(glm::dot(desc.rotation * Vec3(1.0, 0.0, 0.0), Vec3(0.0, 0.0, -1.0)), 1.0, 1e-12);
}

TEST(EnvironmentMap, SamplingEstimatesTheIntegralOverTheTexelsAndAgreesWithItsPdf) {
    const Image image = skyWithSun(64, 32);
    const glm::dmat3 rotation = makeSimilarity(1.0, Vec3(1.0, 2.0, 3.0), 40.0, Vec3(0.0)).rotation;
    const EnvironmentMap map(image, 1.0, rotation);
    const Rgb exact = integralOverTexels(image);
    Rng rng(7, 0);
    Rgb sum(0.0);
    const int n = 200000;
    for (int i = 0; i < n; ++i) {
        const EnvironmentMap::Sample s = map.sample(rng.uniform(), rng.uniform());
        ASSERT_GT(s.pdf, 0.0);
        EXPECT_NEAR(map.pdf(s.toward) / s.pdf, 1.0, 1e-6);
        EXPECT_EQ(map.radiance(s.toward), s.radiance);
        sum += s.radiance / s.pdf;
    }
    // Importance sampling in proportion to L sin(t) at each row's centre leaves only
    // sin's variation within a row: well under 1% at this count.
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(sum[c] / n / exact[c], 1.0, 0.01) << c;
    // The pdf integrates to 1 over the sphere (uniform directions).
    double integral = 0.0;
    for (int i = 0; i < n; ++i) {
        const double z = 1.0 - 2.0 * rng.uniform(), phi = 2.0 * kPi * rng.uniform();
        const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
        integral += map.pdf(Vec3(r * std::cos(phi), z, r * std::sin(phi))) * 4.0 * kPi;
    }
    EXPECT_NEAR(integral / n, 1.0, 0.05);  // the sun's texel holds 96% of the density: a noisy estimate
}

TEST(EnvironmentMap, ItsDirectionalLightsCarryItsIrradianceOnEveryPlane) {
    const Image image = skyWithSun(64, 32);
    const EnvironmentMap map(image, 1.0, glm::dmat3(1.0));
    const std::vector<Light> lights = map.asDirectionalLights(64);
    ASSERT_EQ(lights.size(), 64u);  // none black
    // The irradiance on planes facing up, down and sideways, against the sum over texels.
    for (const Vec3 normal : {Vec3(0, 1, 0), Vec3(0, -1, 0), Vec3(1, 0, 0), Vec3(0, 0, 1)}) {
        Rgb exact(0.0), drawn(0.0);
        for (int y = 0; y < image.height; ++y)
            for (int x = 0; x < image.width; ++x) {
                // The texel's solid angle and direction, fine enough for a cosine.
                const double solidAngle = 2.0 * kPi / image.width *
                                          (std::cos(kPi * y / image.height) - std::cos(kPi * (y + 1) / image.height));
                exact += Rgb(image.at(x, y)) * solidAngle *
                         std::max(0.0, glm::dot(conventionDirection(x, y, image.width, image.height), normal));
            }
        for (const Light& l : lights) drawn += l.power * std::max(0.0, glm::dot(-l.direction, normal));
        // The sun carries most of it, and every light in its texel lands within it.
        EXPECT_NEAR(drawn.r / exact.r, 1.0, 0.05) << normal.x << normal.y << normal.z;
    }
}

TEST(EnvironmentMap, AMapOfOneRadianceIsSampledOverTheWholeSphere) {
    Image image(8, 4);
    for (auto& p : image.pixels) p = glm::vec3(1.0f);
    const EnvironmentMap map(image, 3.0, glm::dmat3(1.0));
    Rgb sum(0.0);
    for (const Light& l : map.asDirectionalLights(128)) sum += l.power;
    EXPECT_NEAR(sum.g / (4.0 * kPi * 3.0), 1.0, 0.02);
    // A black map: no light, no NaN.
    const EnvironmentMap black(Image(8, 4), 1.0, glm::dmat3(1.0));
    EXPECT_TRUE(black.asDirectionalLights(16).empty());
}

using test::errorOf;

EnvironmentDesc fileDesc(const std::filesystem::path& file) {
    EnvironmentDesc d;
    d.file = file;
    return d;
}

void writeExr(const std::filesystem::path& file, int width, int height, float value) {
    std::vector<Imf::Rgba> pixels(size_t(width) * height, Imf::Rgba(1.0f, 1.0f, 1.0f, 1.0f));
    pixels[0] = Imf::Rgba(value, value, value, 1.0f);
    Imf::RgbaOutputFile out(file.c_str(), width, height, Imf::WRITE_RGBA);
    out.setFrameBuffer(pixels.data(), 1, size_t(width));
    out.writePixels(height);
}

TEST(EnvironmentMap, ReadsRadianceHdrAndOpenExr) {
    test::ScratchDir dir;
    std::vector<float> rgb(8 * 4 * 3, 0.5f);
    rgb[3 * (2 * 8 + 5) + 1] = 7.0f;
    const std::filesystem::path hdr = dir.path() / "sky.hdr";
    ASSERT_TRUE(stbi_write_hdr(hdr.c_str(), 8, 4, 3, rgb.data()));
    const auto map = EnvironmentMap::load(fileDesc(hdr));
    EXPECT_EQ(map->width(), 8);
    EXPECT_NEAR(map->radiance(conventionDirection(5, 2, 8, 4)).g, 7.0, 0.05);  // RGBE keeps 8 bits of mantissa
    EXPECT_NEAR(map->radiance(conventionDirection(1, 1, 8, 4)).r, 0.5, 0.01);
    const std::filesystem::path exr = dir.path() / "sky.exr";
    writeExr(exr, 6, 3, 2.0f);
    const auto fromExr = EnvironmentMap::load(fileDesc(exr));
    EXPECT_EQ(fromExr->height(), 3);
    EXPECT_EQ(fromExr->radiance(conventionDirection(0, 0, 6, 3)), Rgb(2.0));
}

TEST(EnvironmentMap, HostileMapFilesGetOneErrorNamingTheFile) {
    test::ScratchDir dir;
    EXPECT_CONTAINS(errorOf([&] { EnvironmentMap::load(fileDesc(dir.path() / "none.hdr")); }), "none.hdr: cannot open");
    EXPECT_CONTAINS(errorOf([&] { EnvironmentMap::load(fileDesc(dir.path())); }), "directory");
    EXPECT_CONTAINS(errorOf([&] { EnvironmentMap::load(fileDesc(dir.write("sky.png", "x"))); }),
                    "unknown environment map format '.png'");
    EXPECT_CONTAINS(errorOf([&] { EnvironmentMap::load(fileDesc(dir.write("text.hdr", "hello"))); }),
                    "not a Radiance HDR");
    // A header that claims 30000 x 30000 texels, and no data: refused before any allocation.
    EXPECT_CONTAINS(errorOf([&] {
                        EnvironmentMap::load(fileDesc(
                            dir.write("huge.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 30000 +X 30000\n")));
                    }),
                    "each side must be 1 to 16384");
    // A valid header and too few texels.
    EXPECT_CONTAINS(errorOf([&] {
                        EnvironmentMap::load(fileDesc(dir.write(
                            "short.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 4 +X 4\n\x80\x80\x80\x81")));
                    }),
                    "short.hdr: Radiance HDR file ends before its last texel");
    // A run-length encoded map (stb writes one for a width of 8 or more) cut short.
    std::vector<float> rgb(16 * 4 * 3, 0.25f);
    const std::filesystem::path whole = dir.path() / "whole.hdr";
    ASSERT_TRUE(stbi_write_hdr(whole.c_str(), 16, 4, 3, rgb.data()));
    EXPECT_NO_THROW(EnvironmentMap::load(fileDesc(whole)));
    std::filesystem::resize_file(whole, std::filesystem::file_size(whole) - 5);
    EXPECT_CONTAINS(errorOf([&] { EnvironmentMap::load(fileDesc(whole)); }),
                    "whole.hdr: Radiance HDR file ends before its last texel");
    // Infinity and NaN in a half-float map.
    const std::filesystem::path inf = dir.path() / "inf.exr", nan = dir.path() / "nan.exr";
    writeExr(inf, 4, 2, std::numeric_limits<float>::infinity());
    writeExr(nan, 4, 2, std::numeric_limits<float>::quiet_NaN());
    EXPECT_CONTAINS(errorOf([&] { EnvironmentMap::load(fileDesc(inf)); }), "inf.exr: environment map texel (0, 0)");
    EXPECT_CONTAINS(errorOf([&] { EnvironmentMap::load(fileDesc(nan)); }), "is negative or not finite");
    writeExr(nan, 4, 2, -1.0f);
    EXPECT_CONTAINS(errorOf([&] { EnvironmentMap::load(fileDesc(nan)); }), "is negative or not finite");
    // Finite, but past the single-precision images once scaled.
    writeExr(nan, 4, 2, 60000.0f);
    EnvironmentDesc scaled = fileDesc(nan);
    scaled.scale = 1e27;
    EXPECT_CONTAINS(errorOf([&] { EnvironmentMap::load(scaled); }), "texel (0, 0) times the scale exceeds 1e30");
    EXPECT_CONTAINS(errorOf([&] { EnvironmentMap::load(fileDesc(dir.write("bad.exr", "garbage bytes"))); }),
                    "bad.exr: cannot read OpenEXR environment map");
}

TEST(EnvironmentMap, TheSceneTakesOneEnvironmentWithItsKeys) {
    const std::string head =
        R"({"camera": {"position": [0, 0, 5], "target": [0, 0, 0], "fov_y": 40, "width": 8, "height": 8},)";
    const std::string tail =
        R"("objects": [{"mesh": "m.obj", "medium": {"sigma_t": 1, "albedo": 0.5}, "samples": "s.lsf"}],
           "render": {"background": true}})";
    const SceneDesc scene = parseSceneText(head + R"("lights": [{"type": "environment", "file": "sky.hdr", "scale": 2,
                             "rotate": {"axis": [0, 1, 0], "degrees": 90}},
                            {"type": "point", "position": [1, 2, 3], "intensity": 1}],)" +
                                               tail,
                                           "/scenes/a.json");
    ASSERT_TRUE(scene.environment);
    EXPECT_EQ(scene.environment->file, std::filesystem::path("/scenes/sky.hdr"));
    EXPECT_EQ(scene.environment->scale, 2.0);
    EXPECT_NEAR(glm::dot(scene.environment->rotation * Vec3(1, 0, 0), Vec3(0, 0, -1)), 1.0, 1e-12);
    EXPECT_EQ(scene.lights.size(), 1u);
    EXPECT_TRUE(scene.render.background);
    EXPECT_CONTAINS(errorOf([&] {
                        parseSceneText(head + R"("lights": [{"type": "environment", "file": "a.hdr"},
                                                            {"type": "environment", "file": "b.hdr"}],)" +
                                           tail,
                                       "two.json");
                    }),
                    "two.json: /lights/1: a second environment light");
    EXPECT_CONTAINS(errorOf([&] {
                        parseSceneText(
                            head + R"("lights": [{"type": "environment", "file": "a.hdr", "scale": -1}],)" + tail,
                            "neg.json");
                    }),
                    "neg.json: /lights/0/scale: must lie in");
    EXPECT_CONTAINS(errorOf([&] {
                        parseSceneText(
                            head + R"("lights": [{"type": "environment", "file": "a.hdr", "sun": 1}],)" + tail,
                            "key.json");
                    }),
                    "/lights/0/sun: unknown key");
    // Room among the 256 lights for the directional lights it becomes.
    std::string many = R"("lights": [{"type": "environment", "file": "a.hdr"})";
    for (int i = 0; i < 129; ++i) many += R"(, {"type": "point", "position": [1, 2, 3], "intensity": 1})";
    EXPECT_CONTAINS(errorOf([&] { parseSceneText(head + many + "]," + tail, "many.json"); }),
                    "many.json: /lights: holds 129 lights beside an environment; at most 128");
}

}  // namespace
}  // namespace lucent
