#include "core/sample_set.h"

#include <gtest/gtest.h>
#include <xxhash.h>

#include <cmath>
#include <cstring>

#include <fstream>

#include "core/error.h"
#include "tests/support/test_support.h"

namespace lucent {
namespace {

SampleSet makeSamples(size_t n, uint32_t channels = 3) {
    SampleSet s;
    s.shOrder = 3;
    s.channels = channels;
    s.sceneFingerprint = 0x1234;
    s.bounds.extend(Vec3(-1));
    s.bounds.extend(Vec3(2));
    s.parameters.seed = 42;
    for (size_t i = 0; i < n; ++i) {
        s.positions.emplace_back(float(i), 0.5f, -0.25f);
        s.radii.push_back(0.1f + float(i));
        s.widths.push_back(0.05f + float(i));
        s.weights.push_back(0.5f + float(i));
        s.extinction.emplace_back(2.0f, 3.0f, 4.0f);
        s.region.emplace_back(-1.0f, 0.5f + float(i));
        s.image.emplace_back(float(i), 1.5f, -0.25f);
        BoundaryBall ball;
        ball.normal = glm::vec3(0.0f, 0.6f, 0.8f);
        ball.depth = 0.1f * float(i);
        ball.curvature = 0.5f;
        ball.share = 0.25f;
        s.boundary.push_back(ball);
        for (size_t k = 0; k < s.coefficientsPerSample(); ++k) s.sh.push_back(float(i * 100 + k));
        s.truncationError.push_back(0.01f);
    }
    return s;
}

std::vector<char> bytesOf(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void writeBytes(const std::filesystem::path& file, const std::vector<char>& bytes) {
    std::ofstream(file, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
}

std::string readError(const std::filesystem::path& file) {
    try {
        readSampleFile(file);
    } catch (const Error& e) {
        return e.what();
    }
    return "no error";
}

TEST(SampleFile, RoundTrips) {
    test::ScratchDir dir;
    SampleSet s = makeSamples(7);
    s.parameters.placementScale = 0.025f;
    writeSampleFile(dir.path() / "s.lsf", s);
    const SampleSet r = readSampleFile(dir.path() / "s.lsf");
    EXPECT_EQ(r.size(), 7u);
    EXPECT_EQ(r.parameters.placementScale, 0.025f);
    EXPECT_EQ(r.shOrder, 3u);
    EXPECT_EQ(r.channels, 3u);
    EXPECT_EQ(r.sceneFingerprint, 0x1234u);
    EXPECT_EQ(r.parameters.seed, 42u);
    EXPECT_EQ(r.positions, s.positions);
    EXPECT_EQ(r.coefficients(), s.sh);
    EXPECT_EQ(r.widths, s.widths);
    EXPECT_EQ(r.extinction, s.extinction);
    EXPECT_EQ(r.region, s.region);
    EXPECT_EQ(r.image, s.image);
    ASSERT_EQ(r.boundary.size(), s.boundary.size());
    EXPECT_EQ(r.boundary[2].normal, s.boundary[2].normal);
    EXPECT_EQ(r.boundary[2].depth, s.boundary[2].depth);
    EXPECT_EQ(r.boundary[2].curvature, s.boundary[2].curvature);
    EXPECT_EQ(r.boundary[2].share, s.boundary[2].share);
    EXPECT_EQ(r.bounds.max, Vec3(2));
    // No temporary file is left next to it.
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()), {}), 1);
}

// A tetrahedron, outward.
TriangleMesh tetrahedron() {
    TriangleMesh m;
    m.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
    m.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    return m;
}

std::string coefficientsError(const SampleSet& s) {
    try {
        (void)s.coefficients();
    } catch (const Error& e) {
        return e.what();
    }
    return "no error";
}

// The coefficients stay in the file until asked for (core/sample_set.h). 12 000
// samples of 27 floats hold 1.3 MB of them: read and checked in two pieces.
TEST(SampleFile, ReadsTheCoefficientsWhenAskedAndNoticesAChangedFile) {
    test::ScratchDir dir;
    const std::filesystem::path file = dir.path() / "s.lsf";
    SampleSet s = makeSamples(12000);
    for (BoundaryBall& b : s.boundary) b.depth = 0.1f;  // inside every ball's sphere
    writeSampleFile(file, s);
    const SampleSet first = readSampleFile(file), second = readSampleFile(file), third = readSampleFile(file);
    EXPECT_EQ(first.coefficients(), s.sh);
    const std::vector<float> before = s.sh;
    const std::string changed = file.string() + ": sample file changed since it was read";
    // A new file renamed over it (what preprocessing does), one coefficient different.
    s.sh[300000] += 1.0f;
    writeSampleFile(file, s);
    EXPECT_NE(coefficientsError(second).find(changed), std::string::npos) << coefficientsError(second);
    // The file changed in place, one bit.
    const SampleSet fourth = readSampleFile(file);
    const size_t at = bytesOf(file).size() / 2;  // the coefficients are 44% to 98% of this file
    {
        std::fstream inPlace(file, std::ios::binary | std::ios::in | std::ios::out);
        inPlace.seekg(std::streamoff(at));
        const char c = char(inPlace.get() ^ 1);
        inPlace.seekp(std::streamoff(at));
        inPlace.put(c);
    }
    EXPECT_NE(coefficientsError(fourth).find(changed), std::string::npos) << coefficientsError(fourth);
    // Once read they stay read, whatever happens to the file; gone, they cannot be.
    std::filesystem::remove(file);
    EXPECT_EQ(first.coefficients(), before);
    EXPECT_NE(coefficientsError(third).find(file.string()), std::string::npos) << coefficientsError(third);
    // A NaN in the second piece is refused when the file is read.
    s.sh.back() = std::nanf("");
    writeSampleFile(file, s);
    EXPECT_NE(readError(file).find("non-finite value"), std::string::npos);
}

TEST(SampleFile, CarriesTheObjectsMesh) {
    test::ScratchDir dir;
    SampleSet s = makeSamples(3);
    s.mesh = tetrahedron();
    s.mesh.positions[1] = Vec3(double(0.1f), double(-2.5f), double(1e-7f));  // single-precision values survive
    writeSampleFile(dir.path() / "s.lsf", s);
    const SampleSet r = readSampleFile(dir.path() / "s.lsf");
    EXPECT_EQ(r.mesh.positions, s.mesh.positions);
    EXPECT_EQ(r.mesh.triangles, s.mesh.triangles);
    EXPECT_EQ(r.positions, s.positions);
}

// The mesh's words patched, the checksum recomputed as a hostile writer would.
TEST(SampleFile, RejectsAMeshThatCannotBeDrawn) {
    test::ScratchDir dir;
    SampleSet s = makeSamples(2);
    s.mesh = tetrahedron();
    writeSampleFile(dir.path() / "good.lsf", s);
    const std::vector<char> bytes = bytesOf(dir.path() / "good.lsf");
    // The file ends with 4 vertices (12 bytes each), 4 faces (12 bytes each) and the checksum.
    const size_t faces = bytes.size() - 8 - 4 * 12, vertices = faces - 4 * 12;
    auto patched = [&](const std::string& name, size_t offset, const void* value, size_t size) {
        std::vector<char> b = bytes;
        std::memcpy(b.data() + offset, value, size);
        const uint64_t checksum = XXH3_64bits(b.data(), b.size() - 8);
        std::memcpy(b.data() + b.size() - 8, &checksum, 8);
        writeBytes(dir.path() / name, b);
        return readError(dir.path() / name);
    };
    const uint32_t index = 4;
    EXPECT_NE(patched("index.lsf", faces + 5 * 4, &index, 4)
                  .find("index.lsf: sample file holds a mesh face with a vertex index out of range"),
              std::string::npos);
    const float nan = std::nanf("");
    EXPECT_NE(
        patched("nan.lsf", vertices + 4, &nan, 4).find("nan.lsf: sample file holds a mesh vertex that is not finite"),
        std::string::npos);
    const float far = 1e20f;
    EXPECT_NE(patched("far.lsf", vertices, &far, 4).find("beyond 1e13"), std::string::npos);
    // Counts that claim more than the file holds, or overflow when multiplied.
    const uint64_t many = uint64_t(1) << 62;
    EXPECT_NE(patched("many.lsf", vertices - 16, &many, 8).find("many.lsf: sample file holds"), std::string::npos);
    const uint64_t zero = 0;
    EXPECT_NE(patched("nofaces.lsf", vertices - 8, &zero, 8).find("counts need"), std::string::npos);
}

TEST(SampleFile, SkinsHoldNoSamples) {
    test::ScratchDir dir;
    SampleSet skin = makeSamples(0);
    skin.parameters.scheme = SampleScheme::OpticallyThick;
    writeSampleFile(dir.path() / "skin.lsf", skin);
    const SampleSet r = readSampleFile(dir.path() / "skin.lsf");
    EXPECT_EQ(r.size(), 0u);
    EXPECT_EQ(r.parameters.scheme, SampleScheme::OpticallyThick);
}

TEST(SampleFile, RejectsDamagedFiles) {
    test::ScratchDir dir;
    const auto good = dir.path() / "good.lsf";
    writeSampleFile(good, makeSamples(5));
    const std::vector<char> bytes = bytesOf(good);

    auto damaged = [&](const std::string& name, std::vector<char> b) {
        writeBytes(dir.path() / name, b);
        return readError(dir.path() / name);
    };
    std::vector<char> truncated(bytes.begin(), bytes.end() - 20);
    EXPECT_NE(damaged("truncated.lsf", truncated).find("truncated.lsf: sample file holds"), std::string::npos);
    std::vector<char> header(bytes.begin(), bytes.begin() + 16);
    EXPECT_NE(damaged("header.lsf", header).find("truncated"), std::string::npos);
    std::vector<char> magic = bytes;
    magic[0] = 'X';
    EXPECT_NE(damaged("magic.lsf", magic).find("wrong magic number"), std::string::npos);
    std::vector<char> version = bytes;
    version[8] = 9;
    EXPECT_NE(damaged("version.lsf", version).find("version 9 is not supported"), std::string::npos);
    std::vector<char> flipped = bytes;
    flipped[bytes.size() - 30] ^= 0x10;
    EXPECT_NE(damaged("flipped.lsf", flipped).find("checksum does not match"), std::string::npos);
    std::vector<char> grown = bytes;
    grown.push_back(0);
    EXPECT_NE(damaged("grown.lsf", grown).find("counts need"), std::string::npos);
    EXPECT_NE(readError(dir.path() / "absent.lsf").find("cannot open sample file"), std::string::npos);
}

// A field patched at its documented offset (docs/sample-file.md), the checksum
// recomputed: each of the reader's header checks refuses its own field.
TEST(SampleFile, RejectsOutOfRangeHeaderFields) {
    test::ScratchDir dir;
    writeSampleFile(dir.path() / "good.lsf", makeSamples(2));
    const std::vector<char> good = bytesOf(dir.path() / "good.lsf");
    auto patched = [&](size_t offset, uint32_t value) {
        std::vector<char> b = good;
        std::memcpy(b.data() + offset, &value, 4);
        const uint64_t checksum = XXH3_64bits(b.data(), b.size() - 8);
        std::memcpy(b.data() + b.size() - 8, &checksum, 8);
        writeBytes(dir.path() / "p.lsf", b);
        return readError(dir.path() / "p.lsf");
    };
    EXPECT_NE(patched(20, 9).find("SH order 9 is out of range"), std::string::npos);
    EXPECT_NE(patched(24, 2).find("channel count must be 1 or 3"), std::string::npos);
    EXPECT_NE(patched(96, 3).find("unknown sample scheme 3"), std::string::npos);
    EXPECT_NE(patched(100, 4).find("region axis 4 is out of range"), std::string::npos);
    float negative = -1.0f;
    uint32_t bits;
    std::memcpy(&bits, &negative, 4);
    EXPECT_NE(patched(84, bits).find("negative or non-finite parameter"), std::string::npos);
    EXPECT_NE(patched(104, bits).find("placement scale that is not positive"), std::string::npos);
    EXPECT_NE(patched(104, 0).find("placement scale that is not positive"), std::string::npos);
    // The first sample's width: after positions (3N floats) and radii (N).
    EXPECT_NE(patched(108 + 4 * (3 * 2 + 2), 0).find("sample 0 has a non-positive width"), std::string::npos);
    EXPECT_EQ(patched(20, 3), "no error");  // the unchanged value reads back: the patching itself is sound
}

TEST(SampleFile, RejectsInvalidBoundaryBalls) {
    test::ScratchDir dir;
    SampleSet s = makeSamples(3);
    s.boundary[1].share = 1.5f;
    writeSampleFile(dir.path() / "share.lsf", s);
    EXPECT_NE(readError(dir.path() / "share.lsf").find("invalid boundary ball"), std::string::npos);
    s = makeSamples(3);
    s.boundary[2].normal = glm::vec3(0.0f, 0.0f, 2.0f);
    writeSampleFile(dir.path() / "normal.lsf", s);
    EXPECT_NE(readError(dir.path() / "normal.lsf").find("invalid boundary ball"), std::string::npos);
}

TEST(SampleFile, RejectsNegativeCoefficientsAndEmptyRegions) {
    test::ScratchDir dir;
    SampleSet s = makeSamples(3);
    s.extinction[1].g = -1.0f;
    writeSampleFile(dir.path() / "negative.lsf", s);
    EXPECT_NE(readError(dir.path() / "negative.lsf").find("negative coefficient"), std::string::npos);
    s = makeSamples(3);
    s.region[2] = glm::vec2(1.0f, 0.0f);
    writeSampleFile(dir.path() / "region.lsf", s);
    EXPECT_NE(readError(dir.path() / "region.lsf").find("empty region"), std::string::npos);
}

TEST(SampleFile, RejectsNonFiniteValues) {
    test::ScratchDir dir;
    SampleSet s = makeSamples(3);
    s.sh[4] = std::nanf("");
    writeSampleFile(dir.path() / "nan.lsf", s);  // a checksum-valid file that holds a NaN
    EXPECT_NE(readError(dir.path() / "nan.lsf").find("non-finite value"), std::string::npos);
}

}  // namespace
}  // namespace lucent
