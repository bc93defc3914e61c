#include "core/density_field.h"

#include <gtest/gtest.h>
#include <openvdb/openvdb.h>

#include <fstream>

#include "core/error.h"
#include "core/rng.h"
#include "tests/support/test_support.h"

namespace lucent {
namespace {

// Midpoint rule with many steps: an independent, slow check of the exact integrals.
double bruteForceIntegral(const DensityField& field, const Vec3& a, const Vec3& b, int steps = 200000) {
    double sum = 0.0;
    for (int i = 0; i < steps; ++i) sum += field.at(a + (b - a) * ((i + 0.5) / steps));
    return sum * glm::length(b - a) / steps;
}

TEST(LayeredDensity, IntegratesSlabsExactly) {
    Bounds3 box;
    box.extend(Vec3(-1));
    box.extend(Vec3(1));
    const LayeredDensity field(1, {1.0, 4.0, 0.0, 2.0}, box);  // slabs of height 0.5 along y
    EXPECT_DOUBLE_EQ(field.at(Vec3(0, -0.9, 0)), 1.0);
    EXPECT_DOUBLE_EQ(field.at(Vec3(0, -0.2, 0)), 4.0);
    EXPECT_DOUBLE_EQ(field.at(Vec3(0, 0.7, 0)), 2.0);
    // Straight up through the box: 0.5 * (1 + 4 + 0 + 2).
    EXPECT_NEAR(field.integrate(Vec3(0, -1, 0), Vec3(0, 1, 0)), 3.5, 1e-12);
    EXPECT_NEAR(field.integrate(Vec3(0, 1, 0), Vec3(0, -1, 0)), 3.5, 1e-12);
    Rng rng(1, 2);
    for (int i = 0; i < 20; ++i) {
        const Vec3 a(rng.uniform() * 2 - 1, rng.uniform() * 2 - 1, rng.uniform() * 2 - 1);
        const Vec3 b(rng.uniform() * 2 - 1, rng.uniform() * 2 - 1, rng.uniform() * 2 - 1);
        EXPECT_NEAR(field.integrate(a, b), bruteForceIntegral(field, a, b), 1e-4);
    }
}

TEST(GridDensity, TrilinearIntegralIsExact) {
    Bounds3 box;
    box.extend(Vec3(-1, -2, 0));
    box.extend(Vec3(1, 2, 3));
    Rng rng(4, 5);
    std::vector<float> values(5 * 4 * 3);
    for (float& v : values) v = float(rng.uniform() * 3.0);
    const GridDensity field(5, 4, 3, box, values);
    // Nodes reproduce the stored values.
    EXPECT_NEAR(field.at(Vec3(-1, -2, 0)), values[0], 1e-6);
    EXPECT_NEAR(field.at(Vec3(1, 2, 3)), values.back(), 1e-6);
    for (int i = 0; i < 20; ++i) {
        const Vec3 a(rng.uniform() * 3 - 1.5, rng.uniform() * 5 - 2.5, rng.uniform() * 4 - 0.5);
        const Vec3 b(rng.uniform() * 3 - 1.5, rng.uniform() * 5 - 2.5, rng.uniform() * 4 - 0.5);
        const double brute = bruteForceIntegral(field, a, b);
        EXPECT_NEAR(field.integrate(a, b), brute, 1e-4 * std::max(1.0, brute));
    }
}

TEST(GridDensity, RawFileSizeMustMatchDims) {
    test::ScratchDir dir;
    Bounds3 box;
    box.extend(Vec3(0));
    box.extend(Vec3(1));
    const std::string eight(8 * sizeof(float), '\0');
    EXPECT_NO_THROW(loadRawGrid(dir.write("g.raw", eight), 2, 2, 2, box));
    try {
        loadRawGrid(dir.write("short.raw", eight.substr(4)), 2, 2, 2, box);
        FAIL();
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("short.raw: grid file holds 28 bytes but dims [2, 2, 2] need 32"),
                  std::string::npos)
            << e.what();
    }
    float negative[8] = {0, 0, 0, -1, 0, 0, 0, 0};
    std::ofstream(dir.path() / "neg.raw", std::ios::binary).write(reinterpret_cast<char*>(negative), sizeof negative);
    EXPECT_THROW(loadRawGrid(dir.path() / "neg.raw", 2, 2, 2, box), Error);
}

TEST(GridDensity, ReadsOpenVdbFloatGrid) {
    test::ScratchDir dir;
    openvdb::initialize();
    auto grid = openvdb::FloatGrid::create(0.0f);
    grid->setName("density");
    grid->setTransform(openvdb::math::Transform::createLinearTransform(0.5));
    auto access = grid->getAccessor();
    for (int k = 0; k < 3; ++k)
        for (int j = 0; j < 3; ++j)
            for (int i = 0; i < 3; ++i) access.setValue(openvdb::Coord(i, j, k), float(1 + i + 10 * j + 100 * k));
    const auto file = dir.path() / "d.vdb";
    openvdb::io::File(file.string()).write({grid});
    const auto field = loadVdbGrid(file, "density");
    EXPECT_NEAR(field->at(Vec3(0, 0, 0)), 1.0, 1e-6);
    EXPECT_NEAR(field->at(Vec3(1.0, 0.5, 0.5)), 1 + 2 + 10 + 100, 1e-5);
    EXPECT_NEAR(field->at(Vec3(0.25, 0, 0)), 1.5, 1e-5);  // halfway between nodes
    EXPECT_DOUBLE_EQ(field->maximum(), 1 + 2 + 20 + 200);
    EXPECT_THROW(loadVdbGrid(file, "missing"), Error);
}

}  // namespace
}  // namespace lucent
