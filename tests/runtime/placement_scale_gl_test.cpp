// An object's scale is part of its optical size. A CAD solid comes as its
// modeller wrote it (an STL 0.02 to 200 units across) and the scene places it
// with "transform": {"scale": s}; preprocessing must sample it at the size it
// is drawn at. The truth is independent of the placement code: the same solid
// written already at that size, not placed, preprocessed and drawn the same way.
#include <gtest/gtest.h>

#include <array>
#include <fstream>

#include "core/image_compare.h"
#include "core/loaded_scene.h"
#include "preprocess/preprocessor.h"
#include "runtime/ss_method.h"
#include "tests/runtime/ss_helper.h"
#include "tests/support/test_support.h"

namespace lucent {
namespace {

// An L-shaped prism, 2 x 2 x 1 times size, centred on the origin, as an ASCII
// STL (unindexed triangles, as solid modellers export).
std::filesystem::path writeLPrism(const test::ScratchDir& dir, const std::string& name, double size) {
    const std::array<glm::dvec2, 6> outline = {glm::dvec2(0, 0), glm::dvec2(2, 0), glm::dvec2(2, 1),
                                               glm::dvec2(1, 1), glm::dvec2(1, 2), glm::dvec2(0, 2)};
    auto corner = [&](int i, double z) { return size * (Vec3(outline[size_t(i)] - glm::dvec2(1.0), z - 0.5)); };
    std::vector<std::array<Vec3, 3>> faces;
    // Both caps as fans from corner 0, from which the whole outline is seen.
    for (int i = 1; i + 1 < 6; ++i) {
        faces.push_back({corner(0, 1), corner(i, 1), corner(i + 1, 1)});
        faces.push_back({corner(0, 0), corner(i + 1, 0), corner(i, 0)});
    }
    for (int i = 0; i < 6; ++i) {
        const int j = (i + 1) % 6;
        faces.push_back({corner(i, 0), corner(j, 0), corner(j, 1)});
        faces.push_back({corner(i, 0), corner(j, 1), corner(i, 1)});
    }
    const std::filesystem::path file = dir.path() / name;
    std::ofstream out(file);
    out.precision(17);
    out << "solid L\n";
    for (const auto& f : faces) {
        const Vec3 n = glm::normalize(glm::cross(f[1] - f[0], f[2] - f[0]));
        out << "facet normal " << n.x << ' ' << n.y << ' ' << n.z << "\nouter loop\n";
        for (const Vec3& v : f) out << "vertex " << v.x << ' ' << v.y << ' ' << v.z << '\n';
        out << "endloop\nendfacet\n";
    }
    out << "endsolid L\n";
    return file;
}

// The prism 1.6 x 1.6 x 0.8 in the world, sigma_t 6 per world unit (about
// 5 mean free paths through its thickness), lit from the side and the front.
SceneDesc litScene(const std::filesystem::path& mesh, const std::filesystem::path& samples) {
    SceneDesc scene;
    scene.camera = test::squareCamera(Vec3(1.5, 2.0, 4.5), Vec3(0.0), 30.0, 96);
    scene.lights = {test::pointLight(Vec3(3.0, 1.0, 2.5), Rgb(30.0)),
                    test::pointLight(Vec3(-2.0, 3.0, 1.0), Rgb(15.0))};
    ObjectDesc o = test::simpleObject(mesh, 6.0, 0.8);
    o.samples = samples;
    scene.objects = {o};
    return scene;
}

Image preprocessAndRender(const SceneDesc& scene) {
    std::vector<std::string> warnings;
    const auto objects = loadObjects(scene, warnings);
    writeSampleFile(scene.objects[0].samples, preprocessObject(objects[0], qualityPreset("draft")));
    return test::renderSs(scene, false);
}

TEST(PlacementScale, TheRawStlPlacedAtAnyScaleDrawsAsTheMeshScaledBeforehand) {
    test::ScratchDir dir;
    constexpr double kWorldSize = 0.8;
    const Image truth =
        preprocessAndRender(litScene(writeLPrism(dir, "world.stl", kWorldSize), dir.path() / "world.lsf"));
    for (const double s : {0.01, 0.1, 10.0, 100.0}) {
        SceneDesc placed = litScene(writeLPrism(dir, "raw.stl", kWorldSize / s), dir.path() / "raw.lsf");
        placed.objects[0].transform.scale = s;
        const ImageError e = compareImages(preprocessAndRender(placed), truth);
        std::printf("raw STL placed at scale %g: relative RMSE %.2e over %zu pixels, mean ratio %.5f\n", s,
                    e.relativeRmse, e.pixels, e.meanRatio);
        EXPECT_GT(e.pixels, 1500u);
        EXPECT_LT(e.relativeRmse, 0.01) << "scale " << s;  // issue 40's bound
        EXPECT_NEAR(e.meanRatio, 1.0, 0.01) << "scale " << s;
    }
}

// Samples drawn at another optical size than they were made for: exact psi, but
// 8 times larger was measured 2-7 times as far from the reference as fresh
// samples (docs/runtime.md); ss says so before it renders, and within the
// served ratio it says nothing.
TEST(PlacementScale, SsWarnsWhenDrawnBeyondTheSizeItsSamplesServe) {
    test::ScratchDir dir;
    SceneDesc scene = litScene(writeLPrism(dir, "l.stl", 0.8), dir.path() / "l.lsf");
    scene.objects[0].transform.scale = 2.0;
    std::vector<std::string> warnings;
    writeSampleFile(scene.objects[0].samples,
                    preprocessObject(loadObjects(scene, warnings)[0], qualityPreset("draft")));
    auto sizeLines = [&](double scale) {
        scene.objects[0].transform.scale = scale;
        std::vector<std::string> lines;
        for (const std::string& l : SsMethod(SsOptions{}).limitations(loadScene(scene, true), MethodSettings{}))
            if (l.find("optical size") != std::string::npos) lines.push_back(l);
        return lines;
    };
    for (const double served : {0.5, 2.0, 8.0}) EXPECT_TRUE(sizeLines(served).empty()) << "scale " << served;
    const std::vector<std::string> larger = sizeLines(16.0), smaller = sizeLines(0.25);
    ASSERT_EQ(larger.size(), 1u);
    EXPECT_NE(larger[0].find("at 8 times the optical size"), std::string::npos) << larger[0];
    ASSERT_EQ(smaller.size(), 1u);
    EXPECT_NE(smaller[0].find("at 0.125 times"), std::string::npos) << smaller[0];
}

}  // namespace
}  // namespace lucent
