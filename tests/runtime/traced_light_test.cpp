// The traced light (runtime/internal/traced_light.h) against optical depths
// worked out by hand on boxes: sigma_t times the length of the segment inside,
// summed over the objects, in the renderer's world however the volume itself
// stands, and stopped by a blocker. No GL context: the tracing is core's rays.
#include <gtest/gtest.h>

#include <vector>

#include "core/rng.h"
#include "core/volume_object.h"
#include "runtime/internal/traced_light.h"
#include "tests/support/test_support.h"

namespace lucent {
namespace {

Light pointLight(const Vec3& p) { return test::pointLight(p, Rgb(1.0)); }

SampleSet samplesAt(const std::vector<glm::vec3>& positions) {
    SampleSet s;
    s.positions = positions;
    return s;
}

void expectDepth(const glm::vec4& got, const Rgb& want, const char* what) {
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], want[c], 1e-5 * (1.0 + want[c])) << what << ", channel " << c;
    EXPECT_EQ(got.w, 0.0f) << what;
}

TEST(TracedLight, OpticalDepthIsSigmaTimesThePathInside) {
    test::ScratchDir dir;
    ObjectDesc desc = test::simpleObject(test::writeBox(dir, "box.obj", Vec3(-1.0), Vec3(1.0)), 1.0);
    desc.medium.sigmaT = Rgb(1.0, 2.0, 3.0);
    std::vector<std::string> warnings;
    const VolumeObject box(desc, warnings);
    Light sun;
    sun.type = Light::Type::Directional;
    sun.direction = Vec3(0.0, -1.0, 0.0);  // travelling down: the light comes from +y
    sun.power = Rgb(1.0);
    const std::vector<Light> lights = {pointLight(Vec3(5.0, 0.0, 0.0)), pointLight(Vec3(0.5, 0.0, 0.0)), sun};
    // Samples at the centre and at (0, 0.5, -0.5).
    const std::vector<glm::vec4> d = tracedOpticalDepths(
        {{&box, Similarity{}}}, samplesAt({glm::vec3(0.0f), glm::vec3(0.0f, 0.5f, -0.5f)}), Similarity{}, lights);
    ASSERT_EQ(d.size(), 6u);
    expectDepth(d[0], Rgb(1.0, 2.0, 3.0), "centre to a light outside: 1 inside");
    expectDepth(d[1], Rgb(0.5, 1.0, 1.5), "centre to a light inside: 0.5, all inside");
    expectDepth(d[2], Rgb(1.0, 2.0, 3.0), "centre to the sun above: 1 inside");
    // From (0, 0.5, -0.5) to (5, 0, 0): it leaves through x = 1, a fifth of the way.
    const double fifth = glm::length(Vec3(5.0, -0.5, 0.5)) / 5.0;
    expectDepth(d[3], Rgb(1.0, 2.0, 3.0) * fifth, "off centre to a light outside");
    expectDepth(d[5], Rgb(0.5, 1.0, 1.5), "off centre to the sun: 0.5 inside");
}

// The renderer may stand the object elsewhere than its volume does (setPlacement):
// lengths are the renderer's. Every other object on the way adds its own depth.
TEST(TracedLight, FollowsThePlacementAndSumsTheObjectsOnTheWay) {
    test::ScratchDir dir;
    std::vector<std::string> warnings;
    const VolumeObject near(test::simpleObject(test::writeBox(dir, "near.obj", Vec3(-1.0), Vec3(1.0)), 2.0), warnings);
    const VolumeObject far(test::simpleObject(test::writeBox(dir, "far.obj", Vec3(-1.0), Vec3(1.0)), 0.5), warnings);
    // near scaled by 2 about the origin; far moved to x in [4, 6] by the renderer.
    const Similarity twice = makeSimilarity(2.0, Vec3(0.0, 0.0, 1.0), 90.0, Vec3(0.0));
    const Similarity moved = makeSimilarity(1.0, Vec3(0.0, 0.0, 1.0), 0.0, Vec3(5.0, 0.0, 0.0));
    const std::vector<TracedVolume> volumes = {{&near, twice}, {&far, moved}};
    const std::vector<glm::vec4> d =
        tracedOpticalDepths(volumes, samplesAt({glm::vec3(0.0f)}), twice, {pointLight(Vec3(10.0, 0.0, 0.0))});
    ASSERT_EQ(d.size(), 1u);
    // 2 inside near (its half-width scaled by 2) at sigma_t 2, then 2 through far at 0.5.
    expectDepth(d[0], Rgb(2.0 * 2.0 + 2.0 * 0.5), "through both");
}

TEST(TracedLight, ABlockerOnTheWayStopsTheLight) {
    test::ScratchDir dir;
    ObjectDesc desc = test::simpleObject(test::writeBox(dir, "box.obj", Vec3(-1.0), Vec3(1.0)), 1.0);
    desc.medium.blockers = {test::writeBox(dir, "stone.obj", Vec3(0.4, -0.1, -0.1), Vec3(0.6, 0.1, 0.1))};
    std::vector<std::string> warnings;
    const VolumeObject box(desc, warnings);
    const std::vector<glm::vec4> d =
        tracedOpticalDepths({{&box, Similarity{}}}, samplesAt({glm::vec3(0.0f)}), Similarity{},
                            {pointLight(Vec3(5.0, 0.0, 0.0)), pointLight(Vec3(-5.0, 0.0, 0.0))});
    ASSERT_EQ(d.size(), 2u);
    EXPECT_EQ(d[0].w, 1.0f) << "the blocker lies between the sample and the light";
    expectDepth(d[1], Rgb(1.0), "the other way is clear");
}

// Many samples, traced in packets of neighbours: each gets its own depth, and
// each ray ends at its light. The stone lies past the light inside the box, on
// the line each ray would follow beyond it: it must not stop them.
TEST(TracedLight, EverySampleOfAPacketEndsAtItsLight) {
    test::ScratchDir dir;
    ObjectDesc desc = test::simpleObject(test::writeBox(dir, "box.obj", Vec3(-1.0), Vec3(1.0)), 1.0);
    desc.medium.sigmaT = Rgb(1.0, 2.0, 3.0);
    desc.medium.blockers = {test::writeBox(dir, "stone.obj", Vec3(0.7, -0.1, -0.1), Vec3(0.9, 0.1, 0.1))};
    std::vector<std::string> warnings;
    const VolumeObject box(desc, warnings);
    const Vec3 inside(0.5, 0.0, 0.0), outside(0.0, 5.0, 0.0);
    Rng rng(3, 1);
    std::vector<glm::vec3> positions(200);
    for (glm::vec3& p : positions)
        p = glm::vec3(-0.9 + 1.2 * rng.uniform(), 0.1 * (rng.uniform() - 0.5), 0.1 * (rng.uniform() - 0.5));
    const std::vector<glm::vec4> d = tracedOpticalDepths({{&box, Similarity{}}}, samplesAt(positions), Similarity{},
                                                         {pointLight(inside), pointLight(outside)});
    ASSERT_EQ(d.size(), 2 * positions.size());
    for (size_t i = 0; i < positions.size(); ++i) {
        const Vec3 x(positions[i]);
        expectDepth(d[2 * i], Rgb(1.0, 2.0, 3.0) * glm::length(inside - x), "to the light inside");
        // To the light above: out through the face y = 1 (|x|, |z| stay below 1 on the way).
        const double exit = glm::length(outside - x) * (1.0 - x.y) / (outside.y - x.y);
        expectDepth(d[2 * i + 1], Rgb(1.0, 2.0, 3.0) * exit, "to the light outside");
    }
}

}  // namespace
}  // namespace lucent
