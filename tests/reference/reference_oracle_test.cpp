// The single-scattering reference checked in every regime it judges the
// runtime in, each against an answer worked out here without its quadrature:
// Henyey-Greenstein phase functions (a slab in closed form), a grid density
// (linear, against the same medium as many thin layers), an opaque blocker's shadow (closed
// form in a cube), the Phong surface term (at chosen pixels), and a light
// inside the object (an independent Gauss-Legendre quadrature on the exact sphere).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "core/camera_rays.h"
#include "reference/reference_renderer.h"
#include "tests/support/test_support.h"

namespace lucent {
namespace {

Light sun(const Vec3& direction, double irradiance) {
    Light l;
    l.type = Light::Type::Directional;
    l.direction = glm::normalize(direction);
    l.power = Rgb(irradiance);
    return l;
}

// Single scattering off the top of a homogeneous slab of optical thickness b,
// seen at view cosine mu, lit at cosine mu0 with irradiance E (normal to the beam):
//   I = a p(cos) E mu0 / (mu + mu0) (1 - exp(-b (1/mu + 1/mu0))).
TEST(ReferenceOracle, HenyeyGreensteinSlabMatchesTheClosedForm) {
    test::ScratchDir dir;
    const double sigma = 1.5, thickness = 0.8, albedo = 0.9, E = 3.0;
    for (const double g : {0.7, -0.5}) {
        SceneDesc scene;
        ObjectDesc slab = test::simpleObject(
            test::writeBox(dir, "slab.obj", Vec3(-30, -30, 0), Vec3(30, 30, thickness)), sigma, albedo);
        slab.medium.g = g;
        scene.objects = {slab};
        const Vec3 beam = glm::normalize(Vec3(0.6, 0.0, -0.8));  // mu0 = 0.8
        scene.lights = {sun(beam, E)};
        const Vec3 spot(0.0, 0.0, thickness);
        const Vec3 toCamera = glm::normalize(Vec3(-0.3, 0.5, 0.6));
        scene.camera.position = spot + 10.0 * toCamera;
        scene.camera.target = spot;
        scene.camera.up = Vec3(0, 0, 1);
        scene.camera.fovYDegrees = 0.01;
        scene.camera.width = scene.camera.height = 1;
        std::vector<std::string> warnings;
        const auto objects = loadObjects(scene, warnings);
        ReferenceSettings settings;
        settings.tolerance = 1e-6;
        const double got = ReferenceRenderer(scene, objects).render(settings).at(0, 0).g;
        const double mu = toCamera.z, mu0 = -beam.z;
        const double cosine = glm::dot(beam, toCamera);  // propagation in, propagation out (towards the camera)
        const double phase = (1 - g * g) / (4 * kPi * std::pow(1 + g * g - 2 * g * cosine, 1.5));
        const double expected =
            albedo * phase * E * mu0 / (mu + mu0) * (1 - std::exp(-sigma * thickness * (1 / mu + 1 / mu0)));
        EXPECT_NEAR(got, expected, 1e-3 * expected) << "g " << g;
    }
}

// A raw grid varying linearly along y (two nodes: trilinear interpolation is
// exactly linear) against the same medium given as 256 constant layers at the
// grid's values at their mid-planes. A ray crossing a whole slab integrates a
// linear density exactly at its mid-plane value, so the two differ only where a
// path ends inside a slab and through the scattering coefficient's zero-mean
// sawtooth across each slab: the largest difference falls as h^2 (8.6e-3, 2.4e-3,
// 7.7e-4 at 32, 64, 128 slabs), then as h (3.8e-4 at 256), under 1e-3 here.
TEST(ReferenceOracle, LinearGridIsTheMediumOfManyThinLayers) {
    test::ScratchDir dir;
    SceneDesc scene;
    scene.camera.position = Vec3(0.4, 0.3, 5);
    scene.camera.width = scene.camera.height = 12;
    scene.lights = {test::pointLight(Vec3(3, 3, 3), Rgb(10.0))};
    std::vector<std::string> warnings;
    scene.objects = {test::simpleObject(test::modelsDir() / "sphere.obj", 2.0, 0.6)};
    const Bounds3 box = loadObjects(scene, warnings)[0].mesh().bounds();
    const double low = 0.3, high = 2.0;  // density at the bottom and the top of the box
    auto density = [&](double y) { return low + (high - low) * (y - box.min.y) / (box.max.y - box.min.y); };

    ObjectDesc layers = scene.objects[0];
    layers.medium.density.type = DensityDesc::Type::Layers;
    layers.medium.density.axis = 1;
    const int slabs = 256;
    for (int k = 0; k < slabs; ++k)
        layers.medium.density.values.push_back(density(box.min.y + (k + 0.5) * (box.max.y - box.min.y) / slabs));

    ObjectDesc grid = scene.objects[0];
    std::vector<float> values(8);
    for (int i = 0; i < 8; ++i) values[i] = float((i / 2) % 2 ? high : low);  // x fastest, then y: node (i, j, k)
    std::ofstream(dir.path() / "d.raw", std::ios::binary)
        .write(reinterpret_cast<const char*>(values.data()), std::streamsize(values.size() * sizeof(float)));
    grid.medium.density.type = DensityDesc::Type::Grid;
    grid.medium.density.file = dir.path() / "d.raw";
    grid.medium.density.dims[0] = grid.medium.density.dims[1] = grid.medium.density.dims[2] = 2;
    grid.medium.density.bounds = Bounds3{Vec3(-1.5, box.min.y, -1.5), Vec3(1.5, box.max.y, 1.5)};

    ReferenceSettings settings;
    settings.tolerance = 1e-5;
    scene.objects = {layers};
    const Image expected = ReferenceRenderer(scene, loadObjects(scene, warnings)).render(settings);
    scene.objects = {grid};
    const Image got = ReferenceRenderer(scene, loadObjects(scene, warnings)).render(settings);
    size_t lit = 0;
    double worst = 0.0;
    for (size_t i = 0; i < got.pixels.size(); ++i) {
        EXPECT_NEAR(got.pixels[i].g, expected.pixels[i].g, 1e-3 * expected.pixels[i].g + 1e-9) << i;
        if (expected.pixels[i].g > 0.0f) {
            ++lit;
            worst = std::max(worst, std::abs(got.pixels[i].g / expected.pixels[i].g - 1.0));
        }
    }
    std::printf("linear grid against %d layers: largest relative difference %.2e\n", slabs, worst);
    EXPECT_GT(lit, 20u);
}

// The cube [-1, 1]^3 under a sun from +y, with an opaque box [-0.4, 0.4]^3
// inside. A view ray along -z at (x, y): under the box (|x| < 0.4, y < -0.4)
// the points with |z| < 0.4 lie in its shadow; beside or above it nothing is;
// through it the ray stops at its front face z = 0.4. Light reaches a lit point
// through exp(-sigma (1 - y)); the view attenuates by exp(-sigma (1 - z)).
TEST(ReferenceOracle, BlockerShadowFollowsTheBlockersGeometry) {
    test::ScratchDir dir;
    const double sigma = 0.9, albedo = 0.8, E = 2.0;
    SceneDesc scene;
    ObjectDesc cube = test::simpleObject(test::modelsDir() / "cube.obj", sigma, albedo);
    cube.medium.blockers = {test::writeBox(dir, "block.obj", Vec3(-0.4), Vec3(0.4))};
    scene.objects = {cube};
    scene.lights = {sun(Vec3(0, -1, 0), E)};
    std::vector<std::string> warnings;
    const auto objects = loadObjects(scene, warnings);
    const ReferenceRenderer renderer(scene, objects);
    ReferenceSettings settings;
    settings.tolerance = 1e-7;
    const double source = sigma * albedo / (4 * kPi) * E;  // isotropic
    auto along = [&](double x, double y) { return renderer.radiance(Vec3(x, y, 5.0), Vec3(0, 0, -1), settings).g; };
    // The view integral over z in [a, b]: int exp(-sigma (1 - z)) dz.
    auto view = [&](double a, double b) { return (std::exp(-sigma * (1 - b)) - std::exp(-sigma * (1 - a))) / sigma; };
    for (const double y : {-0.7, -0.5}) {
        const double shadowed = source * std::exp(-sigma * (1 - y)) * (view(0.4, 1.0) + view(-1.0, -0.4));
        EXPECT_NEAR(along(0.1, y), shadowed, 1e-4 * shadowed) << "under the blocker at y " << y;
        const double open = source * std::exp(-sigma * (1 - y)) * view(-1.0, 1.0);
        EXPECT_NEAR(along(0.6, y), open, 1e-4 * open) << "beside the blocker at y " << y;
    }
    const double above = source * std::exp(-sigma * (1 - 0.6)) * view(-1.0, 1.0);
    EXPECT_NEAR(along(0.1, 0.6), above, 1e-4 * above);
    const double front = source * std::exp(-sigma * (1 - 0.0)) * view(0.4, 1.0);
    EXPECT_NEAR(along(0.1, 0.0), front, 1e-4 * front);
}

// The surface term at chosen pixels of the cube's +z face, against the
// energy-normalised Phong formula, with a medium too thin to add anything.
TEST(ReferenceOracle, SurfaceTermIsEnergyNormalisedPhong) {
    SceneDesc scene;
    ObjectDesc cube = test::simpleObject(test::modelsDir() / "cube.obj", 1e-9, 0.5);
    SurfaceDesc s;
    s.diffuse = Rgb(0.6, 0.5, 0.4);
    s.specular = Rgb(0.2);
    s.shininess = 20.0;
    cube.surface = s;
    scene.objects = {cube};
    const Light bulb = test::pointLight(Vec3(0.5, 1.5, 3.0), Rgb(7.0));
    scene.lights = {bulb};
    std::vector<std::string> warnings;
    const auto objects = loadObjects(scene, warnings);
    const ReferenceRenderer renderer(scene, objects);
    const Vec3 eye(0.2, 0.1, 4.0);
    for (const Vec3 target : {Vec3(0.0, 0.0, 1.0), Vec3(0.5, -0.3, 1.0), Vec3(-0.7, 0.6, 1.0)}) {
        const Vec3 view = glm::normalize(target - eye);
        const Rgb got = renderer.radiance(eye, view, ReferenceSettings{});
        const Vec3 n(0, 0, 1), toLight = bulb.position - target;
        const double d2 = glm::dot(toLight, toLight);
        const Vec3 l = toLight / std::sqrt(d2);
        const double cosI = glm::dot(n, l);
        const Vec3 r = 2.0 * cosI * n - l;
        const double cosR = std::max(0.0, glm::dot(r, -view));
        for (int c = 0; c < 3; ++c) {
            const double brdf =
                s.diffuse[c] / kPi + s.specular[c] * (s.shininess + 2) / (2 * kPi) * std::pow(cosR, s.shininess);
            const double expected = brdf * 7.0 / d2 * cosI;
            EXPECT_NEAR(got[c], expected, 1e-6 * expected) << c;
        }
    }
}

// A point light inside the unit sphere: along a ray, sigma_s p I / d^2 exp(-sigma d)
// exp(-sigma (t - t0)), with d the distance to the light, all inside the medium;
// integrated here by 512-panel Gauss-Legendre on the exact sphere.
TEST(ReferenceOracle, LightInsideTheObjectMatchesAnIndependentQuadrature) {
    const double sigma = 1.2, albedo = 0.8, I = 3.0;
    SceneDesc scene;
    scene.objects = {test::simpleObject(test::modelsDir() / "sphere.obj", sigma, albedo)};
    const Light bulb = test::pointLight(Vec3(0.3, -0.2, 0.1), Rgb(I));
    scene.lights = {bulb};
    std::vector<std::string> warnings;
    const auto objects = loadObjects(scene, warnings);
    const ReferenceRenderer renderer(scene, objects);
    ReferenceSettings settings;
    settings.tolerance = 1e-7;
    const double gx[5] = {-0.9061798459386640, -0.5384693101056831, 0.0, 0.5384693101056831, 0.9061798459386640};
    const double gw[5] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889, 0.4786286704993665,
                          0.2369268850561891};
    const Vec3 o(0.0, 0.0, 5.0);
    for (const Vec3 aim : {Vec3(0.0, 0.0, 0.0), Vec3(0.3, 0.3, 0.0), Vec3(-0.4, 0.1, 0.0)}) {
        const Vec3 d = glm::normalize(aim - o);
        const double b = glm::dot(o, d), c = glm::dot(o, o) - 1.0, disc = b * b - c;
        const double t0 = -b - std::sqrt(disc), t1 = -b + std::sqrt(disc);
        double expected = 0.0;
        const int panels = 512;
        for (int p = 0; p < panels; ++p) {
            const double a = t0 + (t1 - t0) * p / panels, h = (t1 - t0) / panels;
            for (int k = 0; k < 5; ++k) {
                const double t = a + 0.5 * h * (gx[k] + 1.0);
                const double dist = glm::length(bulb.position - (o + t * d));
                expected += 0.5 * h * gw[k] * sigma * albedo / (4 * kPi) * I / (dist * dist) * std::exp(-sigma * dist) *
                            std::exp(-sigma * (t - t0));
            }
        }
        // The icosphere's chord differs from the sphere's near the entry by far less than this.
        EXPECT_NEAR(renderer.radiance(o, d, settings).g, expected, 3e-3 * expected);
    }
}

}  // namespace
}  // namespace lucent
