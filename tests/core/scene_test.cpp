#include "core/scene.h"

#include <gtest/gtest.h>

#include <sstream>

#include <regex>

#include <fstream>

#include "core/error.h"
#include "tests/support/test_support.h"

namespace lucent {
namespace {

const char* kValid = R"({
  "camera": {"position": [0, 0, 5], "target": [0, 0, 0], "fov_y": 40, "width": 64, "height": 48},
  "lights": [{"type": "point", "position": [3, 3, 3], "intensity": [10, 10, 10]},
             {"type": "directional", "direction": [0, -2, 0], "irradiance": 1}],
  "objects": [{"mesh": "m/sphere.obj",
               "medium": {"sigma_t": [1, 2, 3], "albedo": 0.75, "g": 0.3,
                          "density": {"type": "layers", "axis": "y", "values": [1, 2]}},
               "surface": {"diffuse": [0.8, 0.8, 0.8]},
               "samples": "sphere.lsf"}],
  "render": {"method": "reference", "surface": false}
})";

// Replaces the first occurrence of `from` in the valid scene.
std::string variant(const std::string& from, const std::string& to) {
    std::string s = kValid;
    const size_t at = s.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return s.replace(at, from.size(), to);
}

TEST(Scene, ParsesEveryField) {
    const SceneDesc s = parseSceneText(kValid, "dir/scene.json");
    EXPECT_EQ(s.camera.width, 64);
    EXPECT_EQ(s.camera.up, Vec3(0, 1, 0));
    ASSERT_EQ(s.lights.size(), 2u);
    EXPECT_EQ(s.lights[1].direction, Vec3(0, -1, 0));
    EXPECT_EQ(s.lights[1].power, Rgb(1.0));
    const ObjectDesc& o = s.objects[0];
    EXPECT_EQ(o.name, "sphere.obj");
    EXPECT_EQ(o.mesh, std::filesystem::path("dir/m/sphere.obj"));
    EXPECT_EQ(o.samples, std::filesystem::path("dir/sphere.lsf"));
    EXPECT_EQ(o.medium.sigmaT, Rgb(1, 2, 3));
    EXPECT_EQ(o.medium.albedo, Rgb(0.75));
    EXPECT_DOUBLE_EQ(o.medium.g, 0.3);
    EXPECT_DOUBLE_EQ(o.medium.ior, 1.0);
    EXPECT_EQ(o.medium.density.type, DensityDesc::Type::Layers);
    EXPECT_EQ(o.medium.density.axis, 1);
    ASSERT_TRUE(o.surface.has_value());
    EXPECT_EQ(o.surface->diffuse, Rgb(0.8));
    EXPECT_EQ(s.render.method, "reference");
    EXPECT_FALSE(s.render.surface);
}

TEST(Scene, ErrorsNameFileAndJsonPath) {
    struct Case {
        std::string from, to, message;
    };
    const std::vector<Case> cases = {
        {"\"fov_y\": 40", "\"fov_y\": 40, \"fovy\": 1", "dir/scene.json: /camera/fovy: unknown key"},
        {"\"width\": 64", "\"width\": \"64\"", "dir/scene.json: /camera/width: must be an integer"},
        {"\"sigma_t\": [1, 2, 3]", "\"sigma_t\": [1, -2, 3]",
         "dir/scene.json: /objects/0/medium/sigma_t/1: must lie in"},
        {"\"albedo\": 0.75", "\"albedo\": 1.5", "dir/scene.json: /objects/0/medium/albedo: must lie in [0, 1]"},
        {"\"albedo\": 0.75,", "", "dir/scene.json: /objects/0/medium: missing required key 'albedo'"},
        {"\"type\": \"point\"", "\"type\": \"area\"", "dir/scene.json: /lights/0/type: unknown light type"},
        {"\"values\": [1, 2]", "\"values\": [1, -2]",
         "dir/scene.json: /objects/0/medium/density/values/1: must lie in [0, 1e+30] (got -2)"},
        {"\"direction\": [0, -2, 0]", "\"direction\": [0, 0, 0]", "/lights/1/direction: must not be the zero vector"},
        {"\"position\": [0, 0, 5]", "\"position\": [0, 0, 1e999]", "dir/scene.json: malformed JSON"},
        {"\"samples\": \"sphere.lsf\"}]", "\"samples\": \"sphere.lsf\"}", "dir/scene.json: malformed JSON"},
    };
    for (const Case& c : cases) {
        const std::string message = test::sceneErrorOf(variant(c.from, c.to));
        EXPECT_NE(message.find(c.message), std::string::npos) << "got: " << message << "\nwanted: " << c.message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << "one line: " << message;
    }
}

// KHR_lights_punctual's spot: a point light whose intensity falls off between two cones.
TEST(Scene, SpotLightsParseWithKhrDefaultsAndFallOffAsKhrDefines) {
    const SceneDesc s = parseSceneText(
        variant("{\"type\": \"point\", \"position\": [3, 3, 3], \"intensity\": [10, 10, 10]}",
                "{\"type\": \"spot\", \"position\": [0, 2, 0], \"direction\": [0, -3, 0], \"intensity\": 5}"),
        "dir/scene.json");
    const Light& spot = s.lights[0];
    EXPECT_EQ(spot.type, Light::Type::Point);
    ASSERT_TRUE(spot.spot.has_value());
    EXPECT_EQ(spot.spot->axis, Vec3(0, -1, 0));
    EXPECT_EQ(spot.spot->innerDegrees, 0.0);  // KHR's defaults: 0 and pi/4
    EXPECT_EQ(spot.spot->outerDegrees, 45.0);
    EXPECT_FALSE(s.lights[1].spot.has_value());
    // The falloff at chosen angles, from KHR's definition: 1 on the axis and within the inner
    // cone, 0 at and beyond the outer one, and ((cos a - cos o) / (cos i - cos o))^2 between.
    Light l = spot;
    l.spot->innerDegrees = 20.0;
    l.spot->outerDegrees = 50.0;
    auto at = [&](double degrees) {
        const double a = glm::radians(degrees);
        return spotFalloff(l, Vec3(std::sin(a), -std::cos(a), 0.0));
    };
    EXPECT_DOUBLE_EQ(at(0.0), 1.0);
    EXPECT_DOUBLE_EQ(at(19.9), 1.0);
    EXPECT_NEAR(at(50.0), 0.0, 1e-12);
    EXPECT_EQ(at(90.0), 0.0);
    EXPECT_EQ(at(180.0), 0.0);
    const double halfway = std::acos(0.5 * (std::cos(glm::radians(20.0)) + std::cos(glm::radians(50.0))));
    EXPECT_NEAR(at(glm::degrees(halfway)), 0.25, 1e-12);
    EXPECT_EQ(spotFalloff(s.lights[1], Vec3(1, 0, 0)), 1.0);  // no cone: every direction
    EXPECT_EQ(spot.radius, 0.0);
    const SceneDesc sphere = parseSceneText(
        variant("\"intensity\": [10, 10, 10]}", "\"intensity\": 1, \"radius\": 0.25}"), "dir/scene.json");
    EXPECT_EQ(sphere.lights[0].radius, 0.25);
    EXPECT_EQ(spotCoefficients(s.lights[1]), glm::dvec4(0, 0, 0, 1));
}

TEST(Scene, BadSpotConesAreOneErrorNamingTheKey) {
    const std::string point = "{\"type\": \"point\", \"position\": [3, 3, 3], \"intensity\": [10, 10, 10]}";
    const std::string spot = "{\"type\": \"spot\", \"position\": [0, 2, 0], \"intensity\": 5, ";
    const std::vector<std::pair<std::string, std::string>> cases = {
        {spot + "\"direction\": [0, -1, 0], \"inner_angle\": 30, \"outer_angle\": 30}",
         "/lights/0/inner_angle: must be less than outer_angle"},
        {spot + "\"direction\": [0, -1, 0], \"inner_angle\": 50}", "/lights/0/inner_angle: must be less than"},
        {spot + "\"direction\": [0, -1, 0], \"outer_angle\": 120}", "/lights/0/outer_angle: must lie in"},
        {spot + "\"direction\": [0, -1, 0], \"outer_angle\": 0}", "/lights/0/outer_angle: must lie in"},
        {spot + "\"direction\": [0, -1, 0], \"inner_angle\": -1}", "/lights/0/inner_angle: must lie in"},
        {spot + "\"direction\": [0, 0, 0]}", "/lights/0/direction: must not be the zero vector"},
        {spot + "\"outer_angle\": 30}", "/lights/0: missing required key 'direction'"},
        {spot + "\"direction\": [0, -1, 0], \"radius\": 0.5}", "/lights/0/radius: unknown key"},
        {"{\"type\": \"point\", \"position\": [3, 3, 3], \"intensity\": 1, \"radius\": -0.5}",
         "/lights/0/radius: must lie in"},
    };
    for (const auto& [light, message] : cases) {
        const std::string error = test::sceneErrorOf(variant(point, light));
        EXPECT_NE(error.find(message), std::string::npos) << "got: " << error << "\nwanted: " << message;
        EXPECT_EQ(error.find('\n'), std::string::npos);
    }
}

TEST(Scene, MissingFileIsAnError) {
    try {
        parseScene("/nonexistent/scene.json");
        FAIL();
    } catch (const Error& e) {
        EXPECT_STREQ(e.what(), "/nonexistent/scene.json: cannot open scene file: No such file or directory");
    }
}

TEST(Scene, FingerprintFollowsMeshAndMedium) {
    test::ScratchDir dir;
    dir.write("m.obj", "v 0 0 0\n");
    const std::string scene =
        R"({"camera": {"position": [0,0,5], "target": [0,0,0], "fov_y": 40, "width": 8, "height": 8},
      "lights": [], "objects": [{"mesh": "m.obj", "medium": {"sigma_t": SIGMA, "albedo": ALBEDO}, "samples": "s.lsf"}]})";
    auto with = [&](const std::string& sigma, const std::string& albedo = "0.5") {
        std::string s = scene;
        s.replace(s.find("SIGMA"), 5, sigma);
        s.replace(s.find("ALBEDO"), 6, albedo);
        return parseSceneText(s, dir.path() / "scene.json").objects[0].fingerprint;
    };
    EXPECT_EQ(with("1"), with("1"));
    EXPECT_NE(with("1"), with("2"));
    // The samples do not depend on the boundary's index: every method refracts at draw time.
    EXPECT_EQ(with("1"), with("1, \"ior\": 1.5"));
    EXPECT_NE(with("1, \"ior\": 1.5"), with("2, \"ior\": 1.5"));
    // Nor on the albedo or g: the samples hold weights and attenuation, the albedo and phase are drawn.
    EXPECT_EQ(with("1"), with("1", "[0.9, 0.2, 0.1]"));
    EXPECT_EQ(with("1"), with("1, \"g\": 0.7"));
    EXPECT_NE(with("1", "0.9"), with("2", "0.9"));
    const uint64_t before = with("1");
    dir.write("m.obj", "v 0 0 1\n");
    EXPECT_NE(before, with("1"));
}

// The fingerprint covers the contents of blocker and grid files too: a sample
// file made before either changed no longer belongs to the object.
TEST(Scene, FingerprintFollowsBlockerAndGridContents) {
    test::ScratchDir dir;
    dir.write("m.obj", "v 0 0 0\n");
    dir.write("b.obj", "v 0 0 0\n");
    dir.write("g.raw", std::string(32, '\1'));
    const std::string scene =
        R"({"camera": {"position": [0,0,5], "target": [0,0,0], "fov_y": 40, "width": 8, "height": 8},
      "lights": [], "objects": [{"mesh": "m.obj", "medium": {"sigma_t": 1, "albedo": 0.5, "blockers": ["b.obj"],
      "density": {"type": "grid", "file": "g.raw", "dims": [2, 2, 2], "bounds": [[0, 0, 0], [1, 1, 1]]}},
      "samples": "s.lsf"}]})";
    auto fingerprint = [&] { return parseSceneText(scene, dir.path() / "scene.json").objects[0].fingerprint; };
    const uint64_t before = fingerprint();
    EXPECT_EQ(fingerprint(), before);
    dir.write("b.obj", "v 0 0 2\n");
    const uint64_t blockerChanged = fingerprint();
    EXPECT_NE(blockerChanged, before);
    dir.write("g.raw", std::string(32, '\2'));
    EXPECT_NE(fingerprint(), blockerChanged);
}

// Every key the parser reads (each child("...") and has("...") in core/scene.cpp)
// is named in docs/scene-file.md: a key added to the parser without its entry in
// the reference fails here.
TEST(Scene, EveryKeyTheParserReadsIsInTheReference) {
    auto text = [](const std::filesystem::path& file) {
        std::ifstream in(file);
        std::stringstream s;
        s << in.rdbuf();
        return s.str();
    };
    const std::string parser = text(test::sourceDir() / "core" / "scene.cpp");
    const std::string reference = text(test::sourceDir() / "docs" / "scene-file.md");
    ASSERT_FALSE(parser.empty());
    ASSERT_FALSE(reference.empty());
    const std::regex read(R"re((child|has)\("([a-z_]+)"\))re");
    size_t keys = 0;
    for (std::sregex_iterator it(parser.begin(), parser.end(), read), end; it != end; ++it, ++keys) {
        const std::string key = (*it)[2];
        EXPECT_NE(reference.find("`" + key + "`"), std::string::npos) << "'" << key << "' is not in docs/scene-file.md";
    }
    EXPECT_GT(keys, 30u);
}

}  // namespace
}  // namespace lucent
