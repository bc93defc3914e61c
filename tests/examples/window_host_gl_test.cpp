// Lucent embedded in a windowed host (examples/window_host.cpp) under Xvfb: the
// host loads OpenGL through libepoxy and Lucent through its own loader in one
// process, builds and preprocesses its cube in memory, and moves it every
// frame. The cube's light must travel as far across the frame as the cube
// travels across the view: 1 scene unit at about 3.7 units from a 40-degree
// camera spans about 0.39 of the frame's width.
#include <gtest/gtest.h>

#include <cstdlib>

#include "core/image.h"
#include "tests/support/test_support.h"

namespace lucent {
namespace {

// Centre of the light brighter than the host's floor (0.02), as a fraction of the width; and how many such pixels.
std::pair<double, size_t> lightCentre(const Image& image) {
    double sum = 0.0, weight = 0.0;
    size_t lit = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const double w = std::max(double(image.at(x, y).g) - 0.03, 0.0);
            sum += w * (x + 0.5);
            weight += w;
            lit += w > 0.0;
        }
    return {weight > 0.0 ? sum / weight / image.width : -1.0, lit};
}

TEST(WindowHost, MovesItsInMemoryObjectEveryFrameBesideItsOwnGlLoader) {
    test::ScratchDir dir;
    const auto first = dir.path() / "first.pfm", last = dir.path() / "last.pfm";
    const std::string command = "xvfb-run -a -s '-screen 0 640x480x24' " + std::string(LUCENT_EXAMPLE_WINDOW) +
                                " --frames 8 --first " + first.string() + " --last " + last.string() + " 2> " +
                                (dir.path() / "log.txt").string();
    ASSERT_EQ(std::system(command.c_str()), 0) << command;
    const auto [from, litFirst] = lightCentre(readPfm(first));
    const auto [to, litLast] = lightCentre(readPfm(last));
    EXPECT_GT(litFirst, 300u);
    EXPECT_GT(litLast, 300u);
    std::printf("the cube's light moved from %.3f to %.3f of the width\n", from, to);
    EXPECT_NEAR(to - from, 0.39, 0.12);
}

}  // namespace
}  // namespace lucent
