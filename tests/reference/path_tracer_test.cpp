// The path tracer against published transport solutions, typed in here with
// their sources (the numbers are independent of Lucent):
// - van de Hulst (1980), Multiple Light Scattering, Vol. 1 Table 12: isotropic
//   slab, albedo 0.8, optical thickness 2; reflection and transmission
//   functions at mu = 0.5 (the camera-path estimator, next-event estimation and
//   every scattering order are tested through the rendered radiance).
// - van de Hulst Vol. 2 Table 35: Henyey-Greenstein g = 0.75, albedo 0.9,
//   thickness 2, normal incidence: total diffuse reflectance and transmittance
//   (the free flights and the HG sampling, through the particle walk).
// - DISORT test problem 1b (Stamnes et al., DISOTEST.f): conservative isotropic
//   slab of thickness 0.03125 at grazing incidence mu0 = 0.1: upward flux.
// Each passes within three standard errors of the Monte Carlo estimate or 0.5%,
// whichever is larger. And with one collision per path it is single
// scattering: it must agree with --method reference within its noise.
#include "reference/path_tracer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <cstdio>

#include "core/camera_rays.h"
#include "reference/reference_renderer.h"
#include "tests/reference/spot_radiance.h"
#include "tests/support/test_support.h"

namespace lucent {
namespace {

// A slab [-40, 40]^2 x [0, thickness]: 40 optical depths wide, so that light
// leaving through the sides is negligible.
std::filesystem::path writeSlab(const test::ScratchDir& dir, double thickness) {
    return test::writeBox(dir, "slab.obj", Vec3(-40.0, -40.0, 0.0), Vec3(40.0, 40.0, thickness));
}

ObjectDesc slabObject(const std::filesystem::path& mesh, double albedo, double g) {
    ObjectDesc o = test::simpleObject(mesh, 1.0, albedo);
    o.medium.g = g;
    return o;
}

void expectWithin(double estimate, double standardError, double expected, const char* what) {
    const double tolerance = std::max(3.0 * standardError, 0.005 * std::abs(expected));
    std::printf("%s: %.6g +- %.2g (expected %.6g, %+.2f%%)\n", what, estimate, standardError, expected,
                100.0 * (estimate / expected - 1.0));
    EXPECT_NEAR(estimate, expected, tolerance) << what << " (standard error " << standardError << ")";
}

// Radiance of the slab's top (reflection) or bottom (transmission) seen at mu = 0.5,
// lit by a beam of irradiance pi (F = 1) at mu0: I = mu0 R(mu, mu0), resp. mu0 T(mu, mu0).
void expectVanDeHulstTable12(double mu0, bool reflection, double expected) {
    test::ScratchDir dir;
    SceneDesc scene;
    scene.objects = {slabObject(writeSlab(dir, 2.0), 0.8, 0.0)};
    Light beam;
    beam.type = Light::Type::Directional;
    beam.direction = glm::normalize(Vec3(std::sqrt(1.0 - mu0 * mu0), 0.0, -mu0));
    beam.power = Rgb(kPi);
    scene.lights = {beam};
    // Seen from 60 degrees off the normal, across the beam's plane (isotropic scattering: R has no azimuth).
    const double sinView = std::sqrt(0.75);
    const Vec3 spot(0.0, 0.0, reflection ? 2.0 : 0.0);
    scene.camera.position = spot + 10.0 * Vec3(0.0, sinView, reflection ? 0.5 : -0.5);
    scene.camera.target = spot;
    scene.camera.up = Vec3(1, 0, 0);
    PathSettings settings;
    settings.samplesPerPixel = 80000;
    const test::SpotRadiance radiance = test::spotRadiance(scene, settings);
    expectWithin(radiance.mean, radiance.standardError, mu0 * expected, reflection ? "mu0 R" : "mu0 T");
}

TEST(PathTracer, IsotropicSlabReflectionMatchesVanDeHulstTable12) {
    expectVanDeHulstTable12(1.0, true, 0.28616);
    expectVanDeHulstTable12(0.5, true, 0.39102);
}

TEST(PathTracer, IsotropicSlabTransmissionMatchesVanDeHulstTable12) {
    expectVanDeHulstTable12(1.0, false, 0.14864);
    expectVanDeHulstTable12(0.3, false, 0.09425);
}

// Fractions of a beam entering the top at mu0 that leave through the top and
// the bottom, with their standard errors, from n particle walks.
struct Fluxes {
    double up, upError, down, downError;
};
Fluxes slabFluxes(double thickness, double albedo, double g, double mu0, int n,
                  const std::function<void(ObjectDesc&)>& alter = {}) {
    test::ScratchDir dir;
    SceneDesc scene;
    scene.objects = {slabObject(writeSlab(dir, thickness), albedo, g)};
    if (alter) alter(scene.objects.front());
    std::vector<std::string> warnings;
    const std::vector<VolumeObject> objects = loadObjects(scene, warnings);
    const PathTracer tracer(scene, objects);
    const Vec3 beam(std::sqrt(1.0 - mu0 * mu0), 0.0, -mu0);
    double up = 0.0, up2 = 0.0, down = 0.0, down2 = 0.0;
    for (int i = 0; i < n; ++i) {
        PathSampler rng(Rng(7, uint64_t(i)));
        const PathTracer::Exit e = tracer.walk(Vec3(0.0, 0.0, thickness) - (1e-3 / mu0) * beam, beam, rng, 1 << 20, -1);
        if (!e.escaped) continue;
        const double w = e.weight.g;
        (e.direction.z > 0.0 ? up : down) += w;
        (e.direction.z > 0.0 ? up2 : down2) += w * w;
    }
    auto error = [n](double s, double s2) { return std::sqrt(std::max(s2 / n - (s / n) * (s / n), 0.0) / (n - 1)); };
    return {up / n, error(up, up2), down / n, error(down, down2)};
}

TEST(PathTracer, ForwardScatteringSlabMatchesVanDeHulstTable35) {
    const Fluxes f = slabFluxes(2.0, 0.9, 0.75, 1.0, 200000);
    expectWithin(f.up, f.upError, 0.09739, "Rd");
    expectWithin(f.down, f.downError, 0.66096, "Tt");
}

TEST(PathTracer, SlabAtHalfItsMajorantMatchesVanDeHulstTable35) {
    // The same slab as sigma_t 2 at density 0.5, but for its last tenth along x
    // (32 optical depths from the beam, where no walk goes) at 1: the majorant
    // is twice the medium and half the tentative collisions are null: the flights
    // from inside find the boundary at each tentative collision in turn.
    const Fluxes f = slabFluxes(2.0, 0.9, 0.75, 1.0, 200000, [](ObjectDesc& o) {
        o.medium.sigmaT = Rgb(2.0);
        o.medium.density.type = DensityDesc::Type::Layers;
        o.medium.density.axis = 0;
        o.medium.density.values.assign(10, 0.5);
        o.medium.density.values.back() = 1.0;
    });
    expectWithin(f.up, f.upError, 0.09739, "Rd");
    expectWithin(f.down, f.downError, 0.66096, "Tt");
}

TEST(PathTracer, ThinConservativeSlabAtGrazingIncidenceMatchesDisortProblem1b) {
    // DISORT's fluxes are for an incident flux of pi on the horizontal top.
    const Fluxes f = slabFluxes(0.03125, 1.0, 0.0, 0.1, 200000);
    expectWithin(f.up, f.upError, 4.22922e-1 / kPi, "flux up");
    expectWithin(f.down, f.downError, (4.20233e-1 + 2.29844) / kPi, "flux down");
}

// One collision per path is single scattering: the mean over the image agrees
// with the quadrature reference within its noise, for a grey homogeneous
// sphere, an RGB one (one path per channel) and a layered density (delta tracking).
void expectSingleScatteringMatchesReference(ObjectDesc object) {
    SceneDesc scene;
    scene.camera = test::squareCamera(Vec3(0.3, 0.2, 5), Vec3(0), 30, 16);
    scene.lights = {test::pointLight(Vec3(3, 3, 3), Rgb(10.0))};
    scene.objects = {object};
    std::vector<std::string> warnings;
    const std::vector<VolumeObject> objects = loadObjects(scene, warnings);
    ReferenceSettings reference;
    reference.tolerance = 1e-4;
    const Image truth = ReferenceRenderer(scene, objects).render(reference);
    PathSettings settings;
    settings.maxScatter = 1;
    settings.samplesPerPixel = 800;
    const PathTracer::Result r = PathTracer(scene, objects).render(settings);
    for (int c = 0; c < 3; ++c) {
        double path = 0.0, exact = 0.0, variance = 0.0;
        for (size_t i = 0; i < truth.pixels.size(); ++i) {
            path += r.mean.pixels[i][c];
            exact += truth.pixels[i][c];
            variance += std::pow(r.standardError.pixels[i][c], 2);
        }
        ASSERT_GT(exact, 0.0);
        expectWithin(path, std::sqrt(variance), exact, "image sum against the reference");
    }
}

TEST(PathTracer, OneCollisionPerPathIsTheSingleScatteringReference) {
    ObjectDesc grey = test::simpleObject(test::modelsDir() / "sphere.obj", 2.0, 0.75);
    grey.medium.g = 0.5;
    expectSingleScatteringMatchesReference(grey);
    ObjectDesc rgb = test::simpleObject(test::modelsDir() / "sphere.obj", 1.0, 0.75);
    rgb.medium.sigmaT = Rgb(0.5, 1.0, 3.0);
    rgb.medium.albedo = Rgb(0.9, 0.6, 0.3);
    expectSingleScatteringMatchesReference(rgb);
    ObjectDesc layered = test::simpleObject(test::modelsDir() / "sphere.obj", 1.0, 0.8);
    layered.medium.density.type = DensityDesc::Type::Layers;
    layered.medium.density.axis = 1;
    layered.medium.density.values = {0.3, 3.0, 1.0};
    expectSingleScatteringMatchesReference(layered);
}

TEST(PathTracer, NoiseTargetStopsEachPixelAtItsError) {
    // Every lit pixel ends with a standard error within the target of its mean,
    // having taken fewer paths than the cap where the target is easy, and the
    // image agrees with a fixed-count render within their joint noise.
    SceneDesc scene;
    scene.camera = test::squareCamera(Vec3(0, 0, 5), Vec3(0), 30, 12);
    scene.lights = {test::pointLight(Vec3(3, 3, 3), Rgb(10.0))};
    scene.objects = {test::simpleObject(test::modelsDir() / "sphere.obj", 2.0, 0.8)};
    std::vector<std::string> warnings;
    const std::vector<VolumeObject> objects = loadObjects(scene, warnings);
    const PathTracer tracer(scene, objects);
    PathSettings adaptive;
    adaptive.samplesPerPixel = 1 << 16;
    adaptive.noiseTarget = 0.05;
    const PathTracer::Result a = tracer.render(adaptive);
    size_t lit = 0;
    for (size_t i = 0; i < a.mean.pixels.size(); ++i) {
        if (a.mean.pixels[i].g <= 0.0f) continue;
        ++lit;
        for (int c = 0; c < 3; ++c) EXPECT_LE(a.standardError.pixels[i][c], 0.05 * a.mean.pixels[i][c]) << i;
    }
    ASSERT_GT(lit, 40u);
    EXPECT_LT(a.samplesTaken, a.mean.pixels.size() * size_t(adaptive.samplesPerPixel) / 8);
    PathSettings fixed;
    fixed.samplesPerPixel = 512;
    fixed.seed = 9;
    const PathTracer::Result f = tracer.render(fixed);
    double sumA = 0, sumF = 0, var = 0;
    for (size_t i = 0; i < a.mean.pixels.size(); ++i) {
        sumA += a.mean.pixels[i].g;
        sumF += f.mean.pixels[i].g;
        var += std::pow(a.standardError.pixels[i].g, 2) + std::pow(f.standardError.pixels[i].g, 2);
    }
    EXPECT_NEAR(sumA, sumF, 4.0 * std::sqrt(var));
}

TEST(PathTracer, EveryPathAddsTheSurfaceTermOnce) {
    // Each pixel's surface term is found once for all its paths: with the same
    // seed, the images with and without it differ by the reference's surface
    // term exactly, in every channel of a coloured medium (one path a channel).
    SceneDesc scene;
    scene.camera = test::squareCamera(Vec3(0.3, 0.2, 5), Vec3(0), 30, 12);
    scene.lights = {test::pointLight(Vec3(3, 3, 3), Rgb(10.0))};
    ObjectDesc sphere = test::simpleObject(test::modelsDir() / "sphere.obj", 1.0, 0.8);
    sphere.medium.sigmaT = Rgb(0.5, 1.0, 3.0);
    sphere.surface = SurfaceDesc{Rgb(0.3, 0.2, 0.1), Rgb(0.2), 16.0};
    scene.objects = {sphere};
    std::vector<std::string> warnings;
    const std::vector<VolumeObject> objects = loadObjects(scene, warnings);
    const ReferenceRenderer reference(scene, objects);
    ReferenceSettings without;
    without.surface = false;
    const Image exactWith = reference.render(ReferenceSettings{}), exactWithout = reference.render(without);
    const PathTracer tracer(scene, objects);
    PathSettings on, off;
    on.samplesPerPixel = off.samplesPerPixel = 6;
    off.surface = false;
    const Image pathWith = tracer.render(on).mean, pathWithout = tracer.render(off).mean;
    double largest = 0.0;
    for (size_t i = 0; i < exactWith.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            const double exact = exactWith.pixels[i][c] - exactWithout.pixels[i][c];
            largest = std::max(largest, exact);
            EXPECT_NEAR(pathWith.pixels[i][c] - pathWithout.pixels[i][c], exact, 1e-5 * (1.0 + exactWith.pixels[i][c]))
                << i << " " << c;
        }
    EXPECT_GT(largest, 0.01);  // the surface is lit where the camera sees it
}

TEST(PathTracer, HenyeyGreensteinSamplesHaveTheMeanCosineG) {
    // <cos theta> of the HG distribution is g (its defining moment).
    for (double g : {-0.9, -0.3, 0.0, 0.5, 0.95}) {
        const Vec3 dir = glm::normalize(Vec3(0.2, -0.5, 0.8));
        double sum = 0.0;
        const int n = 200000;
        Rng rng(3, uint64_t(g * 1000 + 5000));
        for (int i = 0; i < n; ++i) {
            const double a = rng.uniform(), b = rng.uniform();
            sum += glm::dot(sampleHenyeyGreenstein(dir, g, a, b), dir);
        }
        EXPECT_NEAR(sum / n, g, 0.005) << g;
    }
}

TEST(PathTracer, SameSeedSameImageForAnyThreadCount) {
    SceneDesc scene;
    scene.camera.width = scene.camera.height = 8;
    scene.lights = {test::pointLight(Vec3(3, 3, 3), Rgb(10.0))};
    scene.objects = {test::simpleObject(test::modelsDir() / "sphere.obj", 2.0, 0.9)};
    std::vector<std::string> warnings;
    const std::vector<VolumeObject> objects = loadObjects(scene, warnings);
    PathSettings one, two;
    one.samplesPerPixel = two.samplesPerPixel = 8;
    one.threads = 1;
    two.threads = 2;
    const PathTracer tracer(scene, objects);
    EXPECT_EQ(tracer.render(one).mean.pixels, tracer.render(two).mean.pixels);
    two.seed = 2;
    EXPECT_NE(tracer.render(one).mean.pixels, tracer.render(two).mean.pixels);
}

// Under mpirun each rank renders its RowShare and rank 0 sums the images
// (docs/mpi.md): the shares must cover every row once, leave the others 0, and
// sum to the single-process image bit for bit, for the path tracer and the reference.
TEST(PathTracer, RowSharesOfThreeRanksSumToTheWholeImage) {
    SceneDesc scene;
    scene.camera.width = 6;
    scene.camera.height = 30;  // four bands of 8 rows, the last cut short
    scene.lights = {test::pointLight(Vec3(3, 3, 3), Rgb(10.0))};
    scene.objects = {test::simpleObject(test::modelsDir() / "sphere.obj", 2.0, 0.9)};
    std::vector<std::string> warnings;
    const std::vector<VolumeObject> objects = loadObjects(scene, warnings);
    PathSettings paths;
    paths.samplesPerPixel = 4;
    ReferenceSettings reference;
    const Image wholePaths = PathTracer(scene, objects).render(paths).mean;
    const Image wholeReference = ReferenceRenderer(scene, objects).render(reference);
    Image sumPaths(6, 30), sumReference(6, 30);
    for (int rank = 0; rank < 3; ++rank) {
        paths.rows = reference.rows = RowShare{rank, 3};
        const Image p = PathTracer(scene, objects).render(paths).mean;
        const Image r = ReferenceRenderer(scene, objects).render(reference);
        for (size_t i = 0; i < p.pixels.size(); ++i)
            sumPaths.pixels[i] += p.pixels[i], sumReference.pixels[i] += r.pixels[i];
        for (int y = 0; y < 30; ++y) {
            if (paths.rows.owns(y)) continue;
            EXPECT_EQ(p.at(3, y), glm::vec3(0.0f)) << "rank " << rank << " row " << y;
        }
    }
    EXPECT_EQ(sumPaths.pixels, wholePaths.pixels);
    EXPECT_EQ(sumReference.pixels, wholeReference.pixels);
    double lit = 0.0;
    for (const auto& p : wholePaths.pixels) lit += p.r;
    EXPECT_GT(lit, 0.0);
}

}  // namespace
}  // namespace lucent
