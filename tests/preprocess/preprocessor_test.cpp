#include "preprocess/preprocessor.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <fstream>

#include "core/error.h"
#include "tests/support/test_support.h"

namespace lucent {
namespace {

PreprocessSettings small() {
    PreprocessSettings s = qualityPreset("draft");
    s.samples = 1500;
    return s;
}

TEST(Preprocessor, SphereSamplesAreInsideAndNearTheRequestedCount) {
    std::vector<std::string> warnings;
    const VolumeObject sphere(test::simpleObject(test::modelsDir() / "sphere.obj", 2.0, 0.75), warnings);
    PreprocessTimings timings;
    const SampleSet set = preprocessObject(sphere, small(), &timings);
    EXPECT_NEAR(double(set.size()), 1500.0, 150.0);
    EXPECT_GT(timings.layerCount, 3u);
    const double r = set.parameters.meanRadius;
    for (size_t i = 0; i < set.size(); ++i) {
        const Vec3 p(set.positions[i]);
        EXPECT_LT(glm::length(p), 1.0);
        EXPECT_GE(set.radii[i], 0.5 * r * (1 - 1e-5));
        EXPECT_LE(set.radii[i], 2.0 * r * (1 + 1e-5));
        // FWHM = width factor * radius.
        EXPECT_NEAR(set.widths[i] * 2.0 * std::sqrt(2.0 * std::log(2.0)), small().widthFactor * set.radii[i], 1e-5);
        EXPECT_NEAR(set.scattering[i].g, 1.5, 1e-6);
    }
    EXPECT_EQ(set.sh.size(), set.size() * 16);
}

TEST(Preprocessor, NoSampleInsideABlocker) {
    ObjectDesc desc = test::simpleObject(test::modelsDir() / "cube.obj", 0.8, 0.9);
    desc.medium.blockers = {test::modelsDir() / "torus.obj"};
    std::vector<std::string> warnings;
    const VolumeObject cube(desc, warnings);
    const SampleSet set = preprocessObject(cube, small());
    ASSERT_GT(set.size(), 500u);
    for (const auto& p : set.positions) EXPECT_FALSE(cube.insideBlocker(Vec3(p)));
}

std::vector<char> preprocessedBytes(int threads, const test::ScratchDir& dir) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    std::vector<std::string> warnings;
    const VolumeObject layered([] {
        ObjectDesc d = test::simpleObject(test::modelsDir() / "cube.obj", 1.0, 0.8);
        d.medium.density.type = DensityDesc::Type::Layers;
        d.medium.density.axis = 1;
        d.medium.density.values = {0.5, 4.0};
        return d;
    }(), warnings);
    const auto file = dir.path() / ("t" + std::to_string(threads) + ".lsf");
    writeSampleFile(file, preprocessObject(layered, small()));
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(Preprocessor, SameSeedGivesIdenticalBytesWhateverTheThreadCount) {
    test::ScratchDir dir;
    const auto one = preprocessedBytes(1, dir);
    const auto two = preprocessedBytes(2, dir);
    ASSERT_GT(one.size(), 1000u);
    EXPECT_TRUE(one == two);
}

TEST(Preprocessor, NegligibleLightDepthInvertsE2) {
    // E_2(x) / 2 = 1e-3 at x = 4.39953 (midpoint rule with 2e5 nodes, computed outside the project).
    EXPECT_NEAR(negligibleLightDepth(1.0, 1e-3), 4.39953, 2e-3);
    EXPECT_NEAR(negligibleLightDepth(10.0, 1e-3), 0.439953, 2e-4);
    EXPECT_EQ(negligibleLightDepth(0.0, 1e-3), kInfinity);
}

TEST(Preprocessor, UnknownQualityIsAnError) { EXPECT_THROW(qualityPreset("ultra"), Error); }

}  // namespace
}  // namespace lucent
