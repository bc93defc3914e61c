#include "preprocess/distance_field.h"

#include <gtest/gtest.h>

#include "core/mesh_raycaster.h"
#include "tests/support/test_support.h"

namespace lucent {
namespace {

// Each layer vertex must lie at the layer's depth under the boundary. Marching
// cubes interpolates the distance field linearly inside a voxel, so the stated
// tolerance is a fraction of the voxel size.
void expectLayersAtTheirDepth(const std::string& model, const std::vector<double>& depths, double voxel,
                              double maxError, double meanError) {
    std::vector<std::string> warnings;
    const TriangleMesh mesh = loadClosedMesh(test::modelsDir() / model, warnings);
    const MeshRaycaster boundary(mesh);
    const auto layers = DistanceField::create(mesh, voxel, depths.back())->offsetLayers(depths);
    ASSERT_EQ(layers.size(), depths.size()) << model;
    for (const auto& layer : layers) {
        ASSERT_FALSE(layer.surface.positions.empty());
        double worst = 0.0, sum = 0.0;
        for (const Vec3& p : layer.surface.positions) {
            EXPECT_TRUE(boundary.contains(p));
            const double error = std::abs(boundary.distanceToSurface(p) - layer.depth);
            worst = std::max(worst, error);
            sum += error;
        }
        EXPECT_LT(worst, maxError * voxel) << model << " depth " << layer.depth;
        EXPECT_LT(sum / layer.surface.positions.size(), meanError * voxel) << model << " depth " << layer.depth;
    }
}

TEST(DistanceField, SphereLayersSitAtTheirOffset) {
    expectLayersAtTheirDepth("sphere.obj", {0.025, 0.1, 0.3, 0.6}, 0.05, 0.15, 0.03);
}

TEST(DistanceField, ScannedModelLayersSitAtTheirOffset) {
    // Thin parts (ears) and creases make the distance field kink; the bound is looser.
    expectLayersAtTheirDepth("bunny.off", {0.01, 0.03}, 0.01, 0.6, 0.05);
}

TEST(DistanceField, StopsBelowTheDeepestPoint) {
    std::vector<std::string> warnings;
    const TriangleMesh mesh = loadClosedMesh(test::modelsDir() / "sphere.obj", warnings);
    const auto layers = DistanceField::create(mesh, 0.05, 1.5)->offsetLayers({0.5, 0.9, 1.2, 1.5});
    EXPECT_EQ(layers.size(), 2u);
}

}  // namespace
}  // namespace lucent
