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
// At full resolution the box changes nothing but the pixels it covers. With the
// scattering reduced (the default here: 2000 samples on 96 pixels), the pixels
// it covers are still exactly its colour, and the rest may change only within
// two reduced pixels of its edge, where the upsampling's neighbours behind the
// box count for nothing.
void expectOccluderHidesTheScattering(const std::string& depthFlag, bool fullResolution) {
    test::ScratchDir dir;
    const auto scene = dir.write("scene.json", R"({
      "camera": {"position": [0, 0.6, 5], "target": [0, 0, 0], "fov_y": 35, "width": 96, "height": 96},
      "lights": [{"type": "point", "position": [3, 3, 3], "intensity": [40, 40, 40]}],
      "objects": [{"mesh": ")" + (test::modelsDir() / "sphere.obj").string() +
                                                   R"(",
                   "medium": {"sigma_t": 2.0, "albedo": 0.75}, "samples": "s.lsf"}]})");
    ASSERT_EQ(test::runLucent("preprocess " + scene.string() + " --quality draft --samples 2000").exitCode, 0);
    const std::string resolution = fullResolution ? " --full-resolution" : "";
    const auto run = [&](const std::string& out, const std::string& flag) {
        const std::string command = std::string(LUCENT_EXAMPLE_HOST) + " " + scene.string() + " " +
                                    (dir.path() / out).string() + " " + flag + " " + depthFlag + resolution +
                                    " 2> /dev/null";
        ASSERT_EQ(std::system(command.c_str()), 0) << command;
    };
    run("occluded.pfm", "");
    run("free.pfm", "--no-occluder");
    const Image occluded = readPfm(dir.path() / "occluded.pfm"), free = readPfm(dir.path() / "free.pfm");
    const glm::vec3 boxColour(0.001f, 0.0f, 0.0f);
    size_t hidden = 0, unchanged = 0;
    std::vector<std::pair<int, int>> box, changed;
    for (int y = 0; y < free.height; ++y)
        for (int x = 0; x < free.width; ++x) {
            const glm::vec3 o = occluded.at(x, y), f = free.at(x, y);
            if (o == f) {
                ++unchanged;
            } else if (o == boxColour) {
                box.emplace_back(x, y);  // the box covers it: its own colour, nothing of the sphere added
                if (f.g > 1e-4f) ++hidden;
            } else {
                changed.emplace_back(x, y);
            }
        }
    EXPECT_GT(hidden, 500u);      // the box really stands in front of lit parts of the sphere
    EXPECT_GT(unchanged, 2000u);  // and leaves the rest of the frame alone
    if (fullResolution) {
        EXPECT_TRUE(changed.empty()) << changed.size() << " pixels off the box changed";
        return;
    }
    const int band = 2 * 4;  // two reduced pixels at the largest reduction
    for (const auto& [x, y] : changed) {
        bool nearBox = false;
        for (const auto& [bx, by] : box) nearBox = nearBox || (std::abs(bx - x) <= band && std::abs(by - y) <= band);
        EXPECT_TRUE(nearBox) << "pixel (" << x << ", " << y << ") changed far from the box";
    }
}

TEST(HostProgram, OpaqueOccluderHidesTheScatteringBehindIt) { expectOccluderHidesTheScattering("", true); }

// A host whose depth texture is GL_DEPTH_COMPONENT32F, not DEPTH24_STENCIL8.
TEST(HostProgram, AFloatDepthBufferWorksToo) { expectOccluderHidesTheScattering("--depth32f", true); }

// The default, reduced scattering behind the host's box.
TEST(HostProgram, ReducedScatteringStaysOffTheOccluder) { expectOccluderHidesTheScattering("", false); }

}  // namespace
}  // namespace lucent
