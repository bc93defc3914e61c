// Every bundled scene, --method ss --no-surface at the default quality, against
// --method reference, held to ss's goal for the scene's optical radius
// (tests/runtime/ss_goal.h, docs/accuracy.md): the goal, not a measured value.
#include <gtest/gtest.h>

#include "core/image_compare.h"
#include "core/sample_set.h"
#include "preprocess/preprocessor.h"
#include "reference/reference_renderer.h"
#include "tests/runtime/ss_goal.h"
#include "tests/runtime/ss_helper.h"
#include "tests/support/test_support.h"

namespace lucent {
namespace {

struct Case {
    const char* scene;
    double goal;  // typed from docs/accuracy.md's table, checked against ss_goal.h below
};

class BundledScene : public ::testing::TestWithParam<Case> {};

TEST_P(BundledScene, MeetsTheGoalOfItsOpticalRadius) {
    const Case c = GetParam();
    test::ScratchDir dir;
    SceneDesc scene = parseScene(test::modelsDir() / (std::string(c.scene) + ".json"));
    scene.camera.width = scene.camera.height = 128;
    for (auto& o : scene.objects) o.samples = dir.path() / o.samples.filename();  // keep models/ clean
    const ImageError e = test::ssAgainstReference(scene);
    std::vector<std::string> warnings;
    const auto objects = loadObjects(scene, warnings);
    std::printf("%s: relative RMSE %.4f, MARE %.4f, mean ratio %.4f\n", c.scene, e.relativeRmse,
                e.meanAbsoluteRelativeError, e.meanRatio);
    ASSERT_EQ(test::ssGoalRelativeRmse(objects), c.goal) << "the scene's optical radius changed class";
    EXPECT_GT(e.pixels, 1000u);
    EXPECT_LT(e.relativeRmse, c.goal);
}

INSTANTIATE_TEST_SUITE_P(Models, BundledScene,
                         ::testing::Values(Case{"cube", 0.10}, Case{"torus-cube", 0.10}, Case{"layered-cube", 0.25},
                                           Case{"bunny", 0.25}),
                         [](const auto& info) {
                             std::string name = info.param.scene;
                             name.erase(std::remove(name.begin(), name.end(), '-'), name.end());
                             return name;
                         });

}  // namespace
}  // namespace lucent
