// The hybrid's view pass bends view rays through a grid's refractive index.
// Truth, independent of the shader: in a spherically symmetric index a ray
// keeps n r sin(psi) = b, its impact parameter (Bouguer's formula, the ray's
// angular momentum), whatever the profile across the boundary. In the unit
// sphere of index 1.5 with a uniform source in r < 0.9 and nothing absorbing,
// the ray crosses the source along a straight chord at distance b / n from the
// centre, and carries radiance / n^2 out, less Fresnel's reflection where it
// crosses the boundary at incidence sin i = b (Born and Wolf's angle form):
// L = (1 - R(i)) 2 sqrt(0.81 - b^2 / n^2) / n^2. The straight ray would see
// 2 sqrt(0.81 - b^2), n^2 times brighter.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "core/camera_rays.h"
#include "preprocess/preprocessor.h"
#include "runtime/offscreen_context.h"
#include "runtime/offscreen_frame.h"
#include "runtime/scattering_renderer.h"
#include "tests/support/test_support.h"

namespace lucent {
namespace {

constexpr double kIndex = 1.5, kSourceRadius = 0.9, kShell = 0.04;

// The index: 1.5 inside, 1 outside, a smooth step over the shell |r - 1| < kShell.
double indexAt(double r, double* slope) {
    const double u = std::clamp((1.0 + kShell - r) / (2.0 * kShell), 0.0, 1.0);
    *slope = (u > 0.0 && u < 1.0) ? -(kIndex - 1.0) * 6.0 * u * (1.0 - u) / (2.0 * kShell) : 0.0;
    return 1.0 + (kIndex - 1.0) * u * u * (3.0 - 2.0 * u);
}

ScatteringGrid sphereGrid(bool refracting) {
    ScatteringGrid g;
    const int n = 96;
    g.bounds.min = Vec3(-1.25);
    g.bounds.max = Vec3(1.25);
    g.dims = {n, n, n};
    const double voxel = 2.5 / n;
    g.source.assign(3 * g.voxelCount(), 0.0f);
    g.extinction.assign(3 * g.voxelCount(), 0.0f);
    if (refracting) g.refraction.assign(4 * g.voxelCount(), 0.0f);
    if (refracting) g.ior = kIndex;
    for (int z = 0; z < n; ++z)
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) {
                const size_t i = size_t(x) + size_t(n) * (size_t(y) + size_t(n) * size_t(z));
                const Vec3 p = g.bounds.min + voxel * (Vec3(x, y, z) + 0.5);
                const double r = glm::length(p);
                if (r < kSourceRadius) g.source[3 * i] = g.source[3 * i + 1] = g.source[3 * i + 2] = 1.0f;
                if (!refracting) continue;
                double slope = 0.0;
                g.refraction[4 * i] = float(indexAt(r, &slope));
                const Vec3 gradient = r > 0.0 ? slope * p / r : Vec3(0.0);
                for (int c = 0; c < 3; ++c) g.refraction[4 * i + 1 + c] = float(gradient[c]);
            }
    return g;
}

// 1 - R for unpolarised light from air meeting the sphere at sin i = b.
double transmittedAt(double b) {
    if (b <= 0.0) return 1.0 - std::pow((kIndex - 1.0) / (kIndex + 1.0), 2);
    const double i = std::asin(b), t = std::asin(b / kIndex);
    const double rs = std::sin(i - t) / std::sin(i + t), rp = std::tan(i - t) / std::tan(i + t);
    return 1.0 - 0.5 * (rs * rs + rp * rp);
}

TEST(GridRefraction, ViewRaysBendAsBouguerSaysAndCarryRadianceOverNSquared) {
    SceneDesc scene;
    scene.camera.position = Vec3(0.0, 0.0, 6.0);
    scene.camera.target = Vec3(0.0);
    scene.camera.up = Vec3(0, 1, 0);
    scene.camera.fovYDegrees = 22.0;
    scene.camera.width = scene.camera.height = 64;
    scene.objects = {test::simpleObject(test::modelsDir() / "sphere.obj", 1.0, 0.5)};
    std::vector<std::string> warnings;
    const auto objects = loadObjects(scene, warnings);
    PreprocessSettings settings = qualityPreset("draft");
    settings.samples = 1500;
    const SampleSet samples = preprocessObject(objects[0], settings);

    const auto context = OffscreenContext::create(GlBackend::Auto);
    OffscreenFrame frame(64, 64);
    const ViewSetup view = viewSetupFor(scene.camera, objects[0].mesh().bounds());
    auto render = [&](bool refracting) {
        ScatteringRenderer r;
        r.addObject(translucentObjectFor(objects[0], samples));
        r.addScatteringGrid(sphereGrid(refracting));
        r.setLights({});  // no single scattering: the image is the grid's alone
        DrawOptions options;
        options.surface = false;
        frame.bindAndClear();
        r.draw(view, options);
        return frame.read();
    };
    const Image bent = render(true), straight = render(false);

    const CameraRays rays(scene.camera);
    double bentError = 0.0, straightError = 0.0, bentAgainstStraight = 0.0, norm = 0.0, straightNorm = 0.0;
    int pixels = 0;
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) {
            const Vec3 d = rays.direction(x + 0.5, y + 0.5);
            const double b = glm::length(glm::cross(-rays.origin(), d));
            if (b > 0.95) continue;  // the rim: the tessellated silhouette and the shell
            const double expectBent =
                transmittedAt(b) * 2.0 * std::sqrt(std::max(0.0, 0.81 - b * b / (kIndex * kIndex))) / (kIndex * kIndex);
            const double expectStraight = 2.0 * std::sqrt(std::max(0.0, 0.81 - b * b));
            const double gotBent = bent.at(x, y).g, gotStraight = straight.at(x, y).g;
            bentError += std::pow(gotBent - expectBent, 2);
            bentAgainstStraight += std::pow(gotBent - expectStraight, 2);
            norm += expectBent * expectBent;
            straightError += std::pow(gotStraight - expectStraight, 2);
            straightNorm += expectStraight * expectStraight;
            ++pixels;
        }
    const double bentRmse = std::sqrt(bentError / norm), straightRmse = std::sqrt(straightError / straightNorm);
    const double wrongRmse = std::sqrt(bentAgainstStraight / straightNorm);
    std::printf(
        "%d pixels: bent %.2f%% from Bouguer's chord (1 - R) / n^2, straight %.2f%% from the straight chord; "
        "bent %.1f%% from the straight chord\n",
        pixels, 100.0 * bentRmse, 100.0 * straightRmse, 100.0 * wrongRmse);
    // 3%: the source's edge and the index's shell, trilinear on 96^3 voxels.
    EXPECT_LT(bentRmse, 0.03);
    EXPECT_LT(straightRmse, 0.03);
    EXPECT_GT(wrongRmse, 0.3);
}

}  // namespace
}  // namespace lucent
