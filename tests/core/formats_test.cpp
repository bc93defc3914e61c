// File formats and the error metric against their definitions, never read
// back through the code under test:
// - PFM (Netpbm's definition): "PF", width, height, a negative scale for little
//   endian, then float RGB rows from the bottom of the image to the top;
// - PNG decoded by libpng and EXR by OpenEXR, compared with values computed here;
// - the sample file at the byte offsets docs/sample-file.md gives, with its
//   XXH3-64 checksum computed here by the xxHash library in one call;
// - the metric of core/image_compare.h against values worked out by hand.
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfFrameBuffer.h>
#include <gtest/gtest.h>
#include <xxhash.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>

#include "core/error.h"
#include "core/image.h"
#include "core/image_compare.h"
#include "core/sample_set.h"
#include "tests/support/test_support.h"

namespace lucent {
namespace {

std::vector<char> bytesOf(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    return std::vector<char>((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

template <class T>
T at(const std::vector<char>& bytes, size_t offset) {
    T v;
    std::memcpy(&v, bytes.data() + offset, sizeof v);
    return v;
}

Image threeByTwo() {
    Image image(3, 2);
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 3; ++x) image.at(x, y) = glm::vec3(x + 10 * y, 0.5f * x, 0.25f + y);
    return image;
}

TEST(Formats, PfmBytesFollowTheDefinition) {
    test::ScratchDir dir;
    writeImage(dir.path() / "a.pfm", threeByTwo());
    const std::vector<char> bytes = bytesOf(dir.path() / "a.pfm");
    std::istringstream header(std::string(bytes.begin(), bytes.begin() + std::min<size_t>(bytes.size(), 32)));
    std::string magic;
    int w = 0, h = 0;
    double scale = 0.0;
    header >> magic >> w >> h >> scale;
    EXPECT_EQ(magic, "PF");
    EXPECT_EQ(w, 3);
    EXPECT_EQ(h, 2);
    EXPECT_LT(scale, 0.0);  // little endian
    // The header ends with one whitespace character after the scale.
    const size_t data = size_t(header.tellg()) + 1;
    ASSERT_EQ(bytes.size(), data + 3 * 2 * 3 * sizeof(float));
    // First stored row: the bottom one (y = 1); x = 2 there is (12, 1, 1.25).
    EXPECT_EQ(at<float>(bytes, data + (2 * 3 + 0) * 4), 12.0f);
    EXPECT_EQ(at<float>(bytes, data + (2 * 3 + 1) * 4), 1.0f);
    EXPECT_EQ(at<float>(bytes, data + (2 * 3 + 2) * 4), 1.25f);
    // Second stored row: the top one (y = 0); x = 1 there is (1, 0.5, 0.25).
    EXPECT_EQ(at<float>(bytes, data + ((3 + 1) * 3 + 0) * 4), 1.0f);
    EXPECT_EQ(at<float>(bytes, data + ((3 + 1) * 3 + 2) * 4), 0.25f);
}

// sRGB encoding (IEC 61966-2-1) to 8 bits.
int srgb8(double linear) {
    linear = std::clamp(linear, 0.0, 1.0);
    const double s = linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
    return int(std::lround(255.0 * s));
}

TEST(Formats, PngDecodedByLibpngHoldsTheExposedSrgbValues) {
    test::ScratchDir dir;
    const Image image = threeByTwo();
    writeImage(dir.path() / "a.png", image, 0.05f);
    const test::Png png = test::readPng(dir.path() / "a.png");  // libpng
    ASSERT_EQ(png.width, 3);
    ASSERT_EQ(png.height, 2);
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 3; ++x)
            for (int c = 0; c < 3; ++c)
                EXPECT_EQ(int(png.at(x, y)[c]), srgb8(0.05 * double(image.at(x, y)[c]))) << x << "," << y << "," << c;
}

// Every code on the way: a ramp through [0, 1.2] in 20 000 steps, four decades of
// it near black (where sRGB is linear) and the rest up to white and past it. The
// writer encodes in float and this test in double, so a value within rounding of
// a code's edge may take the neighbouring code; anything more is a wrong code.
TEST(Formats, PngRampHoldsTheSrgbCodeOfEveryValue) {
    test::ScratchDir dir;
    Image ramp(20000, 1);
    for (int x = 0; x < ramp.width; ++x) {
        const double t = double(x) / (ramp.width - 1);
        const double v =
            x < ramp.width / 2 ? 1e-5 * std::pow(1e4, 2.0 * t) : 1.2 * (2.0 * t - 1.0) + 0.1 * (2.0 - 2.0 * t);
        ramp.at(x, 0) = glm::vec3(float(v), float(0.5 * v), float(2.0 * v));
    }
    writeImage(dir.path() / "ramp.png", ramp, 1.0f);
    const test::Png png = test::readPng(dir.path() / "ramp.png");
    ASSERT_EQ(png.width, ramp.width);
    int exact = 0, codes = 0;
    std::vector<bool> seen(256, false);
    for (int x = 0; x < ramp.width; ++x)
        for (int c = 0; c < 3; ++c) {
            const int expected = srgb8(double(ramp.at(x, 0)[c]));
            const int got = png.at(x, 0)[c];
            ASSERT_LE(std::abs(got - expected), 1) << x << "," << c;
            exact += got == expected;
            if (!seen[size_t(got)]) ++codes;
            seen[size_t(got)] = true;
        }
    EXPECT_GE(exact, int(0.999 * 3 * ramp.width));
    EXPECT_EQ(codes, 256);  // the ramp passes through every code
}

TEST(Formats, ExrDecodedByOpenExrHoldsTheLinearFloats) {
    test::ScratchDir dir;
    const Image image = threeByTwo();
    writeImage(dir.path() / "a.exr", image);
    Imf::InputFile exr((dir.path() / "a.exr").c_str());
    const Imath::Box2i window = exr.header().dataWindow();
    ASSERT_EQ(window.max.x - window.min.x + 1, 3);
    ASSERT_EQ(window.max.y - window.min.y + 1, 2);
    std::vector<float> channel[3];
    Imf::FrameBuffer frame;
    const char* names[3] = {"R", "G", "B"};
    for (int c = 0; c < 3; ++c) {
        channel[c].resize(6);
        frame.insert(names[c], Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(channel[c].data()), sizeof(float),
                                          3 * sizeof(float)));
    }
    exr.setFrameBuffer(frame);
    exr.readPixels(window.min.y, window.max.y);
    for (int y = 0; y < 2; ++y)  // EXR rows run from the top
        for (int x = 0; x < 3; ++x)
            for (int c = 0; c < 3; ++c) EXPECT_EQ(channel[c][size_t(y * 3 + x)], image.at(x, y)[c]);
}

TEST(Formats, SampleFileFieldsSitAtTheirDocumentedOffsets) {
    test::ScratchDir dir;
    SampleSet s;
    s.shOrder = 2;
    s.channels = 3;
    s.sceneFingerprint = 0x0123456789abcdefull;
    s.bounds = Bounds3{Vec3(-1, -2, -3), Vec3(4, 5, 6)};
    s.parameters = SampleParameters{77, 32, 128, 9, 0.125f, 0.5f, 1.5f, 1e-3f, SampleScheme::Published, 1, 0.25f};
    s.positions = {{1, 2, 3}};
    s.radii = {0.25f};
    s.widths = {0.75f};
    s.weights = {0.5f};
    s.extinction = {{7, 8, 9}};
    s.region = {{-0.5f, 0.5f}};
    s.image = {{10, 11, 12}};
    s.boundary = {BoundaryBall{{0, 0, 1}, 0.3f, 0.2f, 0.6f}};
    for (int i = 0; i < 12; ++i) s.sh.push_back(0.01f * float(i));
    s.truncationError = {0.125f};
    s.mesh.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
    s.mesh.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    writeSampleFile(dir.path() / "s.lsf", s);
    const std::vector<char> b = bytesOf(dir.path() / "s.lsf");
    EXPECT_EQ(std::string(b.data(), 8), "LUCENTSF");
    EXPECT_EQ(at<uint32_t>(b, 8), 8u);
    EXPECT_EQ(at<uint64_t>(b, 12), 1u);
    EXPECT_EQ(at<uint32_t>(b, 20), 2u);
    EXPECT_EQ(at<uint32_t>(b, 24), 3u);
    EXPECT_EQ(at<uint64_t>(b, 28), 0x0123456789abcdefull);
    EXPECT_EQ(at<float>(b, 36), -1.0f);
    EXPECT_EQ(at<float>(b, 56), 6.0f);
    EXPECT_EQ(at<uint64_t>(b, 60), 77u);
    EXPECT_EQ(at<uint32_t>(b, 68), 32u);
    EXPECT_EQ(at<uint32_t>(b, 72), 128u);
    EXPECT_EQ(at<uint32_t>(b, 76), 9u);
    EXPECT_EQ(at<float>(b, 80), 0.125f);
    EXPECT_EQ(at<float>(b, 84), 0.5f);
    EXPECT_EQ(at<float>(b, 88), 1.5f);
    EXPECT_EQ(at<float>(b, 92), 1e-3f);
    EXPECT_EQ(at<uint32_t>(b, 96), 1u);
    EXPECT_EQ(at<uint32_t>(b, 100), 1u);
    EXPECT_EQ(at<float>(b, 104), 0.25f);
    // The arrays follow in the documented order, N = 1.
    size_t o = 108;
    EXPECT_EQ(at<float>(b, o + 8), 3.0f);  // position z
    o += 12;
    EXPECT_EQ(at<float>(b, o), 0.25f);  // radius
    o += 4;
    EXPECT_EQ(at<float>(b, o), 0.75f);  // width
    o += 4;
    EXPECT_EQ(at<float>(b, o), 0.5f);  // weight w
    o += 4;
    EXPECT_EQ(at<float>(b, o + 4), 8.0f);  // sigma_t g
    o += 12;
    EXPECT_EQ(at<float>(b, o), -0.5f);  // region lo
    o += 8;
    EXPECT_EQ(at<float>(b, o + 8), 12.0f);  // image z
    o += 12;
    EXPECT_EQ(at<float>(b, o + 8), 1.0f);   // ball normal z
    EXPECT_EQ(at<float>(b, o + 12), 0.3f);  // depth
    EXPECT_EQ(at<float>(b, o + 16), 0.2f);  // curvature
    EXPECT_EQ(at<float>(b, o + 20), 0.6f);  // share
    o += 24;
    EXPECT_EQ(at<float>(b, o + 11 * 4), 0.11f);  // the last SH coefficient
    o += 48;
    EXPECT_EQ(at<float>(b, o), 0.125f);  // truncation error
    o += 4;
    EXPECT_EQ(at<uint64_t>(b, o), 4u);      // mesh vertices V
    EXPECT_EQ(at<uint64_t>(b, o + 8), 4u);  // mesh faces T
    o += 16;
    EXPECT_EQ(at<float>(b, o + 3 * 12 + 8), 1.0f);  // the last vertex's z
    o += 4 * 12;
    EXPECT_EQ(at<uint32_t>(b, o + 4), 2u);           // the first face's second corner
    EXPECT_EQ(at<uint32_t>(b, o + 3 * 12 + 8), 3u);  // the last face's third corner
    o += 4 * 12;
    ASSERT_EQ(b.size(), o + 8);
    EXPECT_EQ(at<uint64_t>(b, o), uint64_t(XXH3_64bits(b.data(), o)));  // of every byte before the checksum
}

TEST(Metric, ValuesWorkedOutByHand) {
    // Reference pixels (1,1,1), (2,2,2) and one below 1e-3 of the peak (left out).
    Image reference(3, 1), test(3, 1);
    reference.at(0, 0) = glm::vec3(1.0f);
    reference.at(1, 0) = glm::vec3(2.0f);
    reference.at(2, 0) = glm::vec3(1e-4f);
    test.at(0, 0) = {1.1f, 1.0f, 0.9f};
    test.at(1, 0) = {2.0f, 2.0f, 3.0f};
    test.at(2, 0) = glm::vec3(5.0f);
    const ImageError e = compareImages(test, reference);
    // Differences 0.1, 0, -0.1, 0, 0, 1 over six values of mean 1.5:
    EXPECT_EQ(e.pixels, 2u);
    EXPECT_NEAR(e.relativeRmse, std::sqrt(1.02 / 6.0) / 1.5, 1e-6);
    EXPECT_NEAR(e.meanAbsoluteRelativeError, (0.1 + 0.1 + 0.5) / 6.0, 1e-6);
    EXPECT_NEAR(e.meanRatio, 10.0 / 9.0, 1e-6);
    // A margin of one pixel leaves out the pixel next to the one outside the mask.
    const ImageError interior = compareImages(test, reference, 1);
    EXPECT_EQ(interior.pixels, 0u);
    // In a 5x5 image the margin keeps the 3x3 pixels away from the border (outside the mask).
    Image wide(5, 5), wideTest(5, 5);
    for (auto* image : {&wide, &wideTest})
        for (auto& p : image->pixels) p = glm::vec3(1.0f);
    wideTest.at(2, 2) = glm::vec3(2.0f);
    const ImageError middle = compareImages(wideTest, wide, 1);
    EXPECT_EQ(middle.pixels, 9u);
    EXPECT_NEAR(middle.relativeRmse, std::sqrt(3.0 / 27.0), 1e-6);
    EXPECT_THROW(compareImages(Image(2, 2), Image(2, 3)), Error);
}

}  // namespace
}  // namespace lucent
