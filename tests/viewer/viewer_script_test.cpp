// Viewer script commands without a window: each command's effect on the state,
// and the values the scene parser refuses refused here too.
#include <gtest/gtest.h>

#include "core/error.h"
#include "viewer/viewer_state.h"

namespace lucent {
namespace {

SceneDesc oneLight() {
    SceneDesc scene;
    scene.objects.resize(2);
    scene.objects[1].transform.translation = Vec3(1, 2, 3);
    Light l;
    l.position = Vec3(3, 0, 2);
    l.power = Rgb(40.0);
    scene.lights = {l};
    return scene;
}

TEST(ViewerScript, CommandsChangeWhatTheySay) {
    ViewerState state(oneLight());
    const double distance = glm::length(state.camera.camera().position - state.camera.camera().target);
    applyScriptLine(state, "zoom 0.5", "s:1");
    EXPECT_NEAR(glm::length(state.camera.camera().position - state.camera.camera().target), 0.5 * distance, 1e-9);
    applyScriptLine(state, "light 0 position -3 0 2", "s:2");
    EXPECT_EQ(state.lights[0].position, Vec3(-3, 0, 2));
    applyScriptLine(state, "light 0 radius 0.25", "s:2");
    EXPECT_EQ(state.lights[0].radius, 0.25);
    applyScriptLine(state, "add directional 0 -2e200 0 1 2 3  # a comment", "s:3");
    ASSERT_EQ(state.lights.size(), 2u);
    EXPECT_EQ(state.lights[1].direction, Vec3(0, -1, 0));
    EXPECT_EQ(state.lights[1].power, Rgb(1, 2, 3));
    applyScriptLine(state, "add spot 0 2 0  0 -2 0  10 30  5 5 5", "s:3");
    ASSERT_EQ(state.lights.size(), 3u);
    ASSERT_TRUE(state.lights[2].spot.has_value());
    EXPECT_EQ(state.lights[2].position, Vec3(0, 2, 0));
    EXPECT_EQ(state.lights[2].spot->axis, Vec3(0, -1, 0));
    EXPECT_EQ(state.lights[2].spot->outerDegrees, 30.0);
    applyScriptLine(state, "light 2 direction 1 0 0", "s:3");
    applyScriptLine(state, "light 2 cone 0 60", "s:3");
    EXPECT_EQ(state.lights[2].spot->axis, Vec3(1, 0, 0));
    EXPECT_EQ(state.lights[2].spot->innerDegrees, 0.0);
    EXPECT_EQ(state.lights[2].spot->outerDegrees, 60.0);
    applyScriptLine(state, "remove 2", "s:4");
    applyScriptLine(state, "remove 0", "s:4");
    EXPECT_EQ(state.lights.size(), 1u);
    applyScriptLine(state, "extinction 2.5", "s:5");
    EXPECT_EQ(state.extinctionScale, 2.5f);
    applyScriptLine(state, "exposure -2.5", "s:6");
    EXPECT_EQ(state.exposureStops, -2.5f);
    applyScriptLine(state, "panel off", "s:6");
    EXPECT_FALSE(state.panel);
    applyScriptLine(state, "surface off", "s:7");
    applyScriptLine(state, "scattering off", "s:8");
    EXPECT_FALSE(state.surface || state.scattering);
    EXPECT_TRUE(state.tracedLight);
    applyScriptLine(state, "traced off", "s:8");
    EXPECT_FALSE(state.tracedLight);
    EXPECT_FALSE(state.background);  // the scene's setting
    applyScriptLine(state, "background on", "s:8");
    EXPECT_TRUE(state.background);
    applyScriptLine(state, "screenshot a.png", "s:9");
    applyScriptLine(state, "screenshot b.png panel", "s:9");
    const std::vector<ViewerState::Screenshot> shots = {{"a.png", false}, {"b.png", true}};
    EXPECT_EQ(state.screenshots, shots);
    applyScriptLine(state, "quit", "s:10");
    EXPECT_TRUE(state.quit);
}

// move, rotate and scale change the selected object only, in the world: a turn
// about the world's axis through the object's origin after its own rotation;
// ior changes its index.
TEST(ViewerScript, TheSelectedObjectMovesTurnsScalesAndRefracts) {
    ViewerState state(oneLight());
    ASSERT_EQ(state.placements.size(), 2u);
    EXPECT_EQ(state.placements[1].translation, Vec3(1, 2, 3));
    applyScriptLine(state, "select 1", "s:1");
    applyScriptLine(state, "move 0.5 0 -1", "s:2");
    EXPECT_EQ(state.placements[1].translation, Vec3(1.5, 2, 2));
    EXPECT_TRUE(state.placementsChanged);
    applyScriptLine(state, "rotate 0 0 2 90", "s:3");
    applyScriptLine(state, "rotate 1 0 0 90", "s:4");
    applyScriptLine(state, "scale 2", "s:5");
    // +x: 90 about z -> +y; then 90 about x -> +z; times 2, from the object's origin.
    EXPECT_NEAR(glm::length(state.placements[1].point(Vec3(1, 0, 0)) - Vec3(1.5, 2, 4)), 0.0, 1e-12);
    EXPECT_TRUE(state.placements[0].isIdentity());
    applyScriptLine(state, "ior 1.44", "s:6");
    EXPECT_EQ(state.iors, std::vector<double>({1.0, 1.44}));
    EXPECT_TRUE(state.iorsChanged);
    applyScriptLine(state, "albedo 0.1 0.2 1", "s:7");
    applyScriptLine(state, "g -0.5", "s:8");
    EXPECT_EQ(state.albedos[1], Rgb(0.1, 0.2, 1.0));
    EXPECT_EQ(state.gs[1], -0.5);
    EXPECT_TRUE(state.mediaChanged);
}

TEST(ViewerScript, RefusesWhatTheSceneParserRefuses) {
    const std::pair<const char*, const char*> bad[] = {
        {"light 0 direction 0 0 0", "s:1: direction must not be the zero vector"},
        {"add point 0 0 0 -1 1 1", "s:1: colour must not be negative"},
        {"light 0 colour 1e31 1 1", "s:1: colour must be finite and within +-1e+30"},
        {"light 0 position 1e19 0 0", "s:1: position must be finite and within +-1e+13"},
        {"extinction inf", "s:1: extinction needs a positive finite number"},
        {"exposure 65", "s:1: exposure needs a number of stops in [-64, 64]"},
        {"exposure nan", "s:1: exposure needs a number of stops in [-64, 64]"},
        {"screenshot a.pfm panel", "s:1: a screenshot with the panel is what the window shows: it must be a .png"},
        {"screenshot a.png all", "s:1: screenshot takes a file name and optionally 'panel'"},
        {"panel maybe", "s:1: expected on or off"},
        {"background", "s:1: expected on or off"},
        {"zoom 0", "s:1: zoom needs a positive finite number"},
        {"light 7 position 0 0 0", "s:1: no light with that index (there are 1)"},
        {"fly away", "s:1: unknown command 'fly'"},
        {"select 2", "s:1: no object with that index (there are 2)"},
        {"move 0 0 1e14", "s:1: offset must be finite and within +-1e+13"},
        {"rotate 0 0 0 10", "s:1: direction must not be the zero vector"},
        {"rotate 0 1 0", "s:1: rotate needs an axis and degrees in [-1e6, 1e6]"},
        {"scale -1", "s:1: scale needs a positive finite number"},
        {"scale 1e10", "s:1: scale would leave [1e-09, 1e+09]"},
        {"ior 0.9", "s:1: ior needs an index in [1, 4]"},
        {"ior nan", "s:1: ior needs an index in [1, 4]"},
        {"ior", "s:1: ior needs an index in [1, 4]"},
        {"add spot 0 2 0 0 -1 0 30 30 1 1 1",
         "s:1: a spot's cone needs INNER OUTER in degrees, 0 <= INNER < OUTER <= 90"},
        {"add spot 0 2 0 0 -1 0 10 95 1 1 1",
         "s:1: a spot's cone needs INNER OUTER in degrees, 0 <= INNER < OUTER <= 90"},
        {"add spot 0 2 0 0 -1 0 nan 20 1 1 1",
         "s:1: a spot's cone needs INNER OUTER in degrees, 0 <= INNER < OUTER <= 90"},
        {"light 0 cone 10 20",
         "s:1: light property must be position, direction, colour, (a spot's) cone or (a point's) radius"},
        {"light 0 radius -1", "s:1: a light's radius needs a number in [0, 1e13]"},
        {"add area 0 0 0 1 1 1", "s:1: add needs point, spot or directional"},
        {"albedo 0.5 1.5 0", "s:1: albedo needs three numbers in [0, 1]"},
        {"albedo 0.5 -0.1 0", "s:1: albedo needs three numbers in [0, 1]"},
        {"albedo 0.5 0.5", "s:1: expected three numbers for albedo"},
        {"g 1", "s:1: g needs a mean cosine in [-0.999, 0.999]"},
        {"g nan", "s:1: g needs a mean cosine in [-0.999, 0.999]"},
    };
    for (const auto& [line, message] : bad) {
        ViewerState state(oneLight());
        try {
            applyScriptLine(state, line, "s:1");
            ADD_FAILURE() << line;
        } catch (const Error& e) {
            EXPECT_STREQ(e.what(), message) << line;
        }
    }
}

TEST(ViewerScript, TheEnvironmentScalesAndTurns) {
    SceneDesc scene = oneLight();
    ViewerState without(scene);
    EXPECT_THROW(applyScriptLine(without, "environment scale 2", "s:1"), Error);
    scene.environment = EnvironmentDesc{"sky.hdr", 0.5, glm::dmat3(1.0)};
    ViewerState state(scene);
    EXPECT_TRUE(state.hasEnvironment);
    EXPECT_EQ(state.environmentScale, 0.5);
    state.lightsChanged = false;
    applyScriptLine(state, "environment scale 3", "s:1");
    applyScriptLine(state, "environment turn -90", "s:2");
    EXPECT_EQ(state.environmentScale, 3.0);
    EXPECT_EQ(state.environmentTurnDegrees, -90.0);
    EXPECT_TRUE(state.lightsChanged);
    for (const char* bad : {"environment scale -1", "environment scale nan", "environment scale 1e31",
                            "environment turn inf", "environment spin 3", "environment"})
        EXPECT_THROW(applyScriptLine(state, bad, "s:3"), Error) << bad;
}

// `environment load` asks for a map with or without an environment; the viewer loads it.
TEST(ViewerScript, AnEnvironmentMapIsAskedForByName) {
    ViewerState state(oneLight());
    applyScriptLine(state, "environment load other.hdr  # a sky", "s:1");
    EXPECT_EQ(state.environmentToLoad, "other.hdr");
    EXPECT_FALSE(state.hasEnvironment);  // until the viewer has read it
    EXPECT_THROW(applyScriptLine(state, "environment load", "s:2"), Error);
}

}  // namespace
}  // namespace lucent
