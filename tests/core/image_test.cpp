#include "core/image.h"

#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <csignal>
#include <fstream>

#include "core/error.h"
#include "core/image_compare.h"
#include "tests/support/test_support.h"

namespace lucent {
namespace {

TEST(Image, PfmRoundTripKeepsRowsAndSanitises) {
    test::ScratchDir dir;
    Image image(3, 2);
    image.at(0, 0) = {1, 2, 3};         // top-left
    image.at(2, 1) = {0.5f, 0.25f, 4};  // bottom-right
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

// A write that fails midway (here: past a file-size limit, as on a full disk)
// leaves the existing output as it was and no temporary file behind.
TEST(Image, AWriteFailingMidwayKeepsTheExistingOutput) {
    test::ScratchDir dir;
    const auto target = dir.path() / "a.pfm";
    std::ofstream(target) << "the previous image";
    const pid_t pid = ::fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) {
        std::signal(SIGXFSZ, SIG_IGN);  // the write fails with EFBIG instead of killing
        const rlimit limit{4096, 4096};
        ::setrlimit(RLIMIT_FSIZE, &limit);
        try {
            writeImage(target, Image(64, 64));  // 48 KiB of pixels
        } catch (const Error&) {
            ::_exit(3);
        }
        ::_exit(0);
    }
    int status = 0;
    ::waitpid(pid, &status, 0);
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 3);  // the writer reported the failure
    std::ifstream in(target);
    std::string text;
    std::getline(in, text);
    EXPECT_EQ(text, "the previous image");
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()), {}), 1);
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

namespace lucent {
namespace {

TEST(ImageCompare, LuminanceRelativeRmseIsTheRootOfSquaredErrorOverSquaredTruth) {
    // Grey pixels: luminance is the value (the Rec. 709 weights sum to 1).
    Image truth(2, 1), test(2, 1);
    truth.pixels = {glm::vec3(1.0f), glm::vec3(0.0f)};
    test.pixels = {glm::vec3(1.1f), glm::vec3(5.0f)};  // the unlit truth pixel does not count
    EXPECT_NEAR(luminanceRelativeRmse(test, truth), 0.1, 1e-6);
    truth.pixels = {glm::vec3(1.0f), glm::vec3(3.0f)};
    test.pixels = {glm::vec3(2.0f), glm::vec3(3.0f)};
    EXPECT_NEAR(luminanceRelativeRmse(test, truth), std::sqrt(1.0 / 10.0), 1e-6);
    // Colour: only green moves luminance by its weight 0.7152.
    test.pixels = {glm::vec3(1.0f, 2.0f, 1.0f), glm::vec3(3.0f)};
    EXPECT_NEAR(luminanceRelativeRmse(test, truth), 0.7152 / std::sqrt(10.0), 1e-6);
    EXPECT_THROW(luminanceRelativeRmse(Image(1, 1), truth), Error);
}

TEST(ImageCompare, TheNoiseOfATwiceRenderedReferenceIsTakenOut) {
    // A truth, a test 5% off it everywhere (so 5% relative RMSE), and two
    // references with independent noise of 20% per pixel (std. dev.), as two
    // seeds of a path tracer give. Against their mean the raw error is
    // sqrt(5%^2 + 20%^2 / 2) = 15%; with the noise taken out, 5% again. Over
    // 40 000 pixels the estimate's own spread is about 0.1%; bound 0.5%.
    const int n = 200;
    Image truth(n, n), test(n, n), a(n, n), b(n, n);
    uint64_t state = 12345;
    auto normal = [&] {  // Box-Muller on a 64-bit LCG
        auto uniform = [&] {
            state = state * 6364136223846793005ULL + 1442695040888963407ULL;
            return ((state >> 11) + 0.5) / double(1ULL << 53);
        };
        return std::sqrt(-2.0 * std::log(uniform())) * std::cos(2.0 * kPi * uniform());
    };
    for (size_t i = 0; i < truth.pixels.size(); ++i) {
        const float t = float(1.0 + 0.5 * std::sin(0.01 * double(i)));
        truth.pixels[i] = glm::vec3(t);
        test.pixels[i] = glm::vec3(1.05f * t);
        a.pixels[i] = glm::vec3(t * float(1.0 + 0.2 * normal()));
        b.pixels[i] = glm::vec3(t * float(1.0 + 0.2 * normal()));
    }
    ASSERT_NEAR(luminanceRelativeRmse(test, truth), 0.05, 1e-6);
    const NoisyReferenceError e = luminanceRelativeRmse(test, a, b);
    EXPECT_NEAR(e.noise, 0.2 / std::sqrt(2.0), 0.005);
    EXPECT_NEAR(e.raw, std::sqrt(0.05 * 0.05 + 0.02), 0.005);
    EXPECT_NEAR(e.debiased, 0.05, 0.005);
    // A test equal to the truth: the estimate is near zero, never NaN.
    const NoisyReferenceError exact = luminanceRelativeRmse(truth, a, b);
    EXPECT_LT(exact.debiased, 0.02);
    EXPECT_THROW(luminanceRelativeRmse(Image(1, 1), a, b), Error);
}

TEST(ImageCompare, InteriorPixelsLieTheMarginInsideTheLitOnes) {
    // A lit 6x6 square at (2..7, 3..8) of a 12x12 image, one pixel of it lit
    // below 1e-3 of the peak in one channel: a hole the margin grows around too.
    Image reference(12, 12);
    for (int y = 3; y < 9; ++y)
        for (int x = 2; x < 8; ++x) reference.at(x, y) = glm::vec3(1.0f);
    reference.at(7, 8) = glm::vec3(1.0f, 1.0f, 5e-4f);
    auto lit = [&](int margin) {
        const std::vector<bool> in = interiorPixels(reference, margin);
        int n = 0;
        for (bool b : in) n += b;
        return n;
    };
    EXPECT_EQ(lit(0), 35);
    // One pixel in: the 4x4 square at (3..6, 4..7), but for (6, 7), next to the hole.
    EXPECT_EQ(lit(1), 15);
    EXPECT_TRUE(interiorPixels(reference, 1)[4 * 12 + 3]);
    EXPECT_FALSE(interiorPixels(reference, 1)[7 * 12 + 6]);
    // Two pixels in: the 2x2 square at (4..5, 5..6), but for (5, 6), two from the hole.
    EXPECT_EQ(lit(2), 3);
    EXPECT_EQ(lit(3), 0);
}

}  // namespace
}  // namespace lucent
