#include "core/image.h"

#include <gtest/gtest.h>

#include "core/error.h"
#include "tests/support/test_support.h"

namespace lucent {
namespace {

TEST(Image, PfmRoundTripKeepsRowsAndSanitises) {
    test::ScratchDir dir;
    Image image(3, 2);
    image.at(0, 0) = {1, 2, 3};           // top-left
    image.at(2, 1) = {0.5f, 0.25f, 4};    // bottom-right
    image.at(1, 0) = {std::nanf(""), -1.0f, INFINITY};
    writeImage(dir.path() / "a.pfm", image);
    const Image back = readPfm(dir.path() / "a.pfm");
    EXPECT_EQ(back.at(0, 0), glm::vec3(1, 2, 3));
    EXPECT_EQ(back.at(2, 1), glm::vec3(0.5f, 0.25f, 4));
    EXPECT_EQ(back.at(1, 0), glm::vec3(0.0f));
}

TEST(Image, WritesPngAndExr) {
    test::ScratchDir dir;
    Image image(4, 4);
    image.at(1, 1) = {1, 0.5f, 0.25f};
    writeImage(dir.path() / "a.png", image);
    writeImage(dir.path() / "a.exr", image);
    EXPECT_GT(std::filesystem::file_size(dir.path() / "a.png"), 50u);
    EXPECT_GT(std::filesystem::file_size(dir.path() / "a.exr"), 50u);
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()), {}), 2);
}

TEST(Image, UnwritablePathIsAnErrorAndLeavesNothing) {
    test::ScratchDir dir;
    Image image(2, 2);
    EXPECT_THROW(writeImage(dir.path() / "missing-dir" / "a.png", image), Error);
    EXPECT_THROW(writeImage(dir.path() / "a.bmp", image), Error);
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()), {}), 0);
}

}  // namespace
}  // namespace lucent
