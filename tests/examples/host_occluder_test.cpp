// The library inside someone else's frame: examples/host_occluder.cpp draws a
// floor and an opaque box in front of a translucent sphere with plain OpenGL and
// hands Lucent its depth texture. Where the box stands, not a trace of the
// sphere's scattered light may show; everywhere else the box changes nothing.
#include <gtest/gtest.h>

#include "core/image.h"
#include "tests/support/test_support.h"

namespace lucent {
namespace {

// depthFlag: "" for the host's GL_DEPTH24_STENCIL8, "--depth32f" for GL_DEPTH_COMPONENT32F.
void expectOccluderHidesTheScattering(const std::string& depthFlag) {
    test::ScratchDir dir;
    const auto scene = dir.write("scene.json", R"({
      "camera": {"position": [0, 0.6, 5], "target": [0, 0, 0], "fov_y": 35, "width": 96, "height": 96},
      "lights": [{"type": "point", "position": [3, 3, 3], "intensity": [40, 40, 40]}],
      "objects": [{"mesh": ")" + (test::modelsDir() / "sphere.obj").string() + R"(",
                   "medium": {"sigma_t": 2.0, "albedo": 0.75}, "samples": "s.lsf"}]})");
    ASSERT_EQ(test::runLucent("preprocess " + scene.string() + " --quality draft --samples 2000").exitCode, 0);
    const auto run = [&](const std::string& out, const std::string& flag) {
        const std::string command = std::string(LUCENT_EXAMPLE_HOST) + " " + scene.string() + " " +
                                    (dir.path() / out).string() + " " + flag + " " + depthFlag + " 2> /dev/null";
        ASSERT_EQ(std::system(command.c_str()), 0) << command;
    };
    run("occluded.pfm", "");
    run("free.pfm", "--no-occluder");
    const Image occluded = readPfm(dir.path() / "occluded.pfm"), free = readPfm(dir.path() / "free.pfm");
    const glm::vec3 boxColour(0.001f, 0.0f, 0.0f);
    size_t hidden = 0, unchanged = 0;
    for (size_t i = 0; i < free.pixels.size(); ++i) {
        if (occluded.pixels[i] == free.pixels[i]) {
            ++unchanged;
            continue;
        }
        // The box covers this pixel: exactly its own colour, nothing of the sphere added.
        EXPECT_EQ(occluded.pixels[i], boxColour) << "pixel " << i;
        if (free.pixels[i].g > 1e-4f) ++hidden;
    }
    EXPECT_GT(hidden, 500u);     // the box really stands in front of lit parts of the sphere
    EXPECT_GT(unchanged, 2000u); // and leaves the rest of the frame alone
}

TEST(HostProgram, OpaqueOccluderHidesTheScatteringBehindIt) { expectOccluderHidesTheScattering(""); }

// A host whose depth texture is GL_DEPTH_COMPONENT32F, not DEPTH24_STENCIL8.
TEST(HostProgram, AFloatDepthBufferWorksToo) { expectOccluderHidesTheScattering("--depth32f"); }

}  // namespace
}  // namespace lucent
