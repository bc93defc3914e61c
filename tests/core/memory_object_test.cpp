// A host's object from memory (memoryObject, closedMesh): the same checks as a
// file gets, and a fingerprint that ties sample sets to the very data.
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "core/loaded_scene.h"
#include "core/volume_object.h"
#include "preprocess/preprocessor.h"
#include "tests/support/test_support.h"

namespace lucent {
namespace {

// A box [-h, h]^3 as positions and outward triangles.
struct Soup {
    std::vector<Vec3> positions;
    std::vector<std::array<uint32_t, 3>> triangles;
};
Soup box(double h) {
    Soup s;
    for (int i = 0; i < 8; ++i) s.positions.emplace_back(i & 4 ? h : -h, i & 2 ? h : -h, i & 1 ? h : -h);
    const uint32_t quads[6][4] = {{0, 1, 3, 2}, {4, 6, 7, 5}, {0, 4, 5, 1}, {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 5, 7, 3}};
    for (const auto& q : quads) {
        s.triangles.push_back({q[0], q[1], q[2]});
        s.triangles.push_back({q[0], q[2], q[3]});
    }
    return s;
}

std::string errorOf(const Soup& s) {
    std::vector<std::string> warnings;
    try {
        closedMesh(s.positions, s.triangles, "host mesh", warnings);
    } catch (const Error& e) {
        return e.what();
    }
    return "no error";
}

TEST(MemoryObject, MeshesFromMemoryGetTheChecksFilesGet) {
    std::vector<std::string> warnings;
    const Soup good = box(0.5);
    const TriangleMesh mesh = closedMesh(good.positions, good.triangles, "host mesh", warnings);
    EXPECT_NEAR(mesh.signedVolume(), 1.0, 1e-12);  // the unit cube, faces outward
    Soup open = good;
    open.triangles.pop_back();
    EXPECT_NE(errorOf(open).find("host mesh: mesh is not closed"), std::string::npos) << errorOf(open);
    Soup stray = good;
    stray.triangles[0][1] = 8;
    EXPECT_NE(errorOf(stray).find("host mesh: triangle 0 refers to vertex 8 of 8"), std::string::npos)
        << errorOf(stray);
    Soup infinite = good;
    infinite.positions[3].y = INFINITY;
    EXPECT_NE(errorOf(infinite).find("host mesh: vertex 3 has a non-finite coordinate"), std::string::npos)
        << errorOf(infinite);
    Soup inside = good;
    for (auto& t : inside.triangles) std::swap(t[1], t[2]);
    warnings.clear();
    EXPECT_GT(closedMesh(inside.positions, inside.triangles, "host mesh", warnings).signedVolume(), 0.0);
    ASSERT_EQ(warnings.size(), 1u);  // flipped, and said so
}

TEST(MemoryObject, SamplesBelongToTheDataTheyWereMadeFrom) {
    std::vector<std::string> warnings;
    const Soup small = box(0.5), large = box(0.6);
    MediumDesc medium;
    medium.sigmaT = Rgb(2.0);
    medium.albedo = Rgb(0.8);
    const VolumeObject a = memoryObject("a", closedMesh(small.positions, small.triangles, "a", warnings), medium);
    const VolumeObject same = memoryObject("a", closedMesh(small.positions, small.triangles, "a", warnings), medium);
    const VolumeObject bigger = memoryObject("b", closedMesh(large.positions, large.triangles, "b", warnings), medium);
    MediumDesc denser = medium;
    denser.sigmaT = Rgb(3.0);
    const VolumeObject thicker = memoryObject("c", closedMesh(small.positions, small.triangles, "c", warnings), denser);
    EXPECT_EQ(a.desc().fingerprint, same.desc().fingerprint);
    EXPECT_NE(a.desc().fingerprint, bigger.desc().fingerprint);
    EXPECT_NE(a.desc().fingerprint, thicker.desc().fingerprint);
    PreprocessSettings settings = qualityPreset("draft");
    settings.samples = 500;
    SampleSet samples = preprocessObject(a, settings);
    EXPECT_GT(samples.size(), 100u);
    EXPECT_NO_THROW(checkSamplesBelong(same, samples, "samples of a"));
    EXPECT_THROW(checkSamplesBelong(bigger, samples, "samples of a"), Error);
    EXPECT_THROW(checkSamplesBelong(thicker, samples, "samples of a"), Error);
}

TEST(MemoryObject, AMediumOutOfRangeIsRefused) {
    std::vector<std::string> warnings;
    const Soup s = box(0.5);
    MediumDesc bad;
    bad.sigmaT = Rgb(1.0, NAN, 1.0);
    try {
        memoryObject("host", closedMesh(s.positions, s.triangles, "host", warnings), bad);
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("host: sigma_t must lie in"), std::string::npos) << e.what();
    }
    MediumDesc albedo;
    albedo.albedo = Rgb(1.5);
    EXPECT_THROW(memoryObject("host", closedMesh(s.positions, s.triangles, "host", warnings), albedo), Error);
}

}  // namespace
}  // namespace lucent
