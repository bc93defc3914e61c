// Refracting boundaries in the path tracer, against results computed here
// independently of core/refraction.cpp:
// - Fresnel's equations in their angle form (Born and Wolf, Principles of
//   Optics, 1.5.3: R_s = sin^2(i - t) / sin^2(i + t), R_p = tan^2(i - t) /
//   tan^2(i + t)), and ((n - 1) / (n + 1))^2 at normal incidence;
// - an absorbing slab between two such boundaries: its transmittance and
//   reflectance summed over the internal reflections (a geometric series);
// - the power a sphere takes in from a point light (a one-dimensional
//   quadrature over the cone of directions that meet it) against the power its
//   medium removes from the irradiance that next-event estimation finds through
//   the boundary, integrated over the volume;
// - the single scattering of a half-space under a beam, seen from outside: a
//   closed form with Snell's angles, both Fresnel transmissions and the n^2 law
//   of radiance;
// - the hemispherical reflectance to diffuse light, in Walsh's closed form;
// - light reaching points inside a torus through its concave boundary: by the
//   mesh's first crossing towards the light, with Snell's law there in sines;
// - the path tracer's roulette on that solve: its mean over many draws is the
//   solve's light, and its odds follow the straight line's transmittance.
#include "core/refraction.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "core/loaded_scene.h"
#include "core/rng.h"
#include "reference/light_arrival.h"
#include "reference/path_tracer.h"
#include "reference/reference_renderer.h"
#include "tests/reference/spot_radiance.h"
#include "tests/support/test_support.h"

namespace lucent {
namespace {

double fresnelByAngles(double incident, double n) {
    if (incident == 0.0) return std::pow((n - 1.0) / (n + 1.0), 2);
    const double t = std::asin(std::sin(incident) / n);
    const double rs = std::sin(incident - t) / std::sin(incident + t);
    const double rp = std::tan(incident - t) / std::tan(incident + t);
    return 0.5 * (rs * rs + rp * rp);
}

double radians(double degrees) { return degrees * kPi / 180.0; }

TEST(Refraction, FresnelReflectanceIsTheAngleFormBothWays) {
    for (double n : {1.33, 1.5, 2.4}) {
        EXPECT_NEAR(fresnelReflectance(1.0, 1.0 / n), std::pow((n - 1.0) / (n + 1.0), 2), 1e-12);
        for (double degrees = 1.0; degrees < 90.0; degrees += 2.0) {
            const double i = radians(degrees), t = std::asin(std::sin(i) / n);
            const double expected = fresnelByAngles(i, n);
            EXPECT_NEAR(fresnelReflectance(std::cos(i), 1.0 / n), expected, 1e-12) << n << " " << degrees;
            // From inside at the refracted angle: the same (Stokes' relations).
            EXPECT_NEAR(fresnelReflectance(std::cos(t), n), expected, 1e-12) << n << " " << degrees;
        }
        // Past the critical angle from inside: total reflection.
        EXPECT_EQ(fresnelReflectance(std::cos(std::asin(1.0 / n) + 1e-6), n), 1.0);
    }
}

// The hemispherical reflectance of a smooth boundary to diffuse light from
// outside, in closed form (Walsh 1926; as quoted by Judd, J. Res. NBS 29, 1942,
// eq. 7), n the relative index > 1.
double diffuseExternalReflectance(double n) {
    const double n2 = n * n, n4 = n2 * n2;
    return 0.5 + (n - 1.0) * (3.0 * n + 1.0) / (6.0 * (n + 1.0) * (n + 1.0)) +
           n2 * (n2 - 1.0) * (n2 - 1.0) / std::pow(n2 + 1.0, 3) * std::log((n - 1.0) / (n + 1.0)) -
           2.0 * n2 * n * (n2 + 2.0 * n - 1.0) / ((n2 + 1.0) * (n4 - 1.0)) +
           8.0 * n4 * (n4 + 1.0) / ((n2 + 1.0) * (n4 - 1.0) * (n4 - 1.0)) * std::log(n);
}

TEST(Refraction, DiffuseFresnelReflectanceIsWalshsFormAndReciprocal) {
    for (double n : {1.05, 1.33, 1.5, 1.7, 2.4}) {
        const double external = diffuseExternalReflectance(n);
        EXPECT_NEAR(diffuseFresnelReflectance(1.0 / n), external, 1e-9) << n;
        // Inside, by reciprocity: what the outside does not reflect comes out
        // compressed into the cone within the critical angle, 1 / n^2 of it.
        EXPECT_NEAR(diffuseFresnelReflectance(n), 1.0 - (1.0 - external) / (n * n), 1e-9) << n;
    }
    EXPECT_NEAR(diffuseFresnelReflectance(1.0), 0.0, 1e-12);
}

TEST(Refraction, RefractedDirectionsObeySnellInThePlaneOfIncidence) {
    const Vec3 normal(0.0, 0.0, 1.0);
    for (double degrees : {0.0, 10.0, 45.0, 80.0}) {
        const double i = radians(degrees);
        const Vec3 w(std::sin(i), 0.0, -std::cos(i));
        const std::optional<Vec3> t = refractedDirection(w, normal, 1.0 / 1.5);
        ASSERT_TRUE(t);
        EXPECT_NEAR(glm::length(*t), 1.0, 1e-12);
        EXPECT_NEAR(t->x, std::sin(i) / 1.5, 1e-12);  // sin t = sin i / n, same side
        EXPECT_NEAR(t->y, 0.0, 1e-15);
        EXPECT_LT(t->z, 0.0);
        // And back out along the incident direction.
        const std::optional<Vec3> back = refractedDirection(*t, normal, 1.5);
        ASSERT_TRUE(back);
        EXPECT_NEAR(glm::length(*back - w), 0.0, 1e-12);
    }
    EXPECT_FALSE(refractedDirection(glm::normalize(Vec3(1.0, 0.0, -0.5)), normal, 1.5));  // 63 degrees > 41.8
}

struct Tally {
    double transmitted = 0.0, reflected = 0.0, parallelOut = 0.0;
};

// Analog walks into the slab [-40, 40]^2 x [0, 1] (index n) at incidence
// degrees from its normal; maxScatter 0: a collision ends the walk (absorbed).
Tally walkSlab(double degrees, double n, double albedo, int maxScatter, int walks) {
    test::ScratchDir dir;
    SceneDesc scene;
    ObjectDesc o = test::simpleObject(test::writeBox(dir, "slab.obj", Vec3(-40, -40, 0), Vec3(40, 40, 1)), 1.0, albedo);
    o.medium.ior = n;
    o.medium.g = 0.5;
    scene.objects = {o};
    std::vector<std::string> warnings;
    const std::vector<VolumeObject> objects = loadObjects(scene, warnings);
    const PathTracer tracer(scene, objects);
    const double i = radians(degrees);
    const Vec3 w(std::sin(i), 0.0, -std::cos(i)), origin = Vec3(0.0, 0.0, 1.0) - 3.0 * w;
    Tally tally;
    for (int k = 0; k < walks; ++k) {
        PathSampler rng(Rng(7, uint64_t(k)));
        const PathTracer::Exit e = tracer.walk(origin, w, rng, maxScatter, -1);
        if (!e.escaped) continue;
        if (e.direction.z < 0.0)
            tally.transmitted += 1.0 / walks;
        else
            tally.reflected += 1.0 / walks;
        if (e.direction.z < 0.0 && glm::length(e.direction - w) < 1e-9) tally.parallelOut += 1.0 / walks;
    }
    return tally;
}

void expectProportion(double measured, double expected, int walks, const char* what) {
    const double standardError = std::sqrt(expected * (1.0 - expected) / walks);
    std::printf("%s: %.5f (expected %.5f, standard error %.5f)\n", what, measured, expected, standardError);
    EXPECT_NEAR(measured, expected, std::max(3.0 * standardError, 1e-4)) << what;
}

TEST(Refraction, AbsorbingSlabSumsItsInternalReflections) {
    const double n = 1.5;
    const int walks = 60000;
    for (double degrees : {0.0, 60.0}) {
        const double i = radians(degrees), t = std::asin(std::sin(i) / n);
        const double r = fresnelByAngles(i, n), a = std::exp(-1.0 / std::cos(t));  // one crossing's transmittance
        const double denominator = 1.0 - r * r * a * a;
        const double transmitted = (1.0 - r) * (1.0 - r) * a / denominator;
        const double reflected = r + (1.0 - r) * (1.0 - r) * r * a * a / denominator;
        const Tally tally = walkSlab(degrees, n, 0.0, 0, walks);
        std::printf("incidence %.0f degrees:\n", degrees);
        expectProportion(tally.transmitted, transmitted, walks, "transmitted");
        expectProportion(tally.reflected, reflected, walks, "reflected");
        // Out through the far side parallel to the way in: Snell's law both ways.
        EXPECT_DOUBLE_EQ(tally.parallelOut, tally.transmitted);
    }
}

TEST(Refraction, ConservativeSlabLosesNoParticle) {
    const Tally tally = walkSlab(30.0, 1.5, 1.0, 1 << 20, 4000);
    std::printf("escaped: %.5f\n", tally.transmitted + tally.reflected);
    EXPECT_GT(tally.transmitted + tally.reflected, 0.999);
}

// The unit sphere of index 1.5 and sigma_t 8.
std::vector<VolumeObject> refractingSphere(double albedo) {
    SceneDesc scene;
    ObjectDesc o = test::simpleObject(test::modelsDir() / "sphere.obj", 8.0, albedo);
    o.medium.ior = 1.5;
    scene.objects = {o};
    std::vector<std::string> warnings;
    return loadObjects(scene, warnings);
}

TEST(Refraction, SphereRemovesThePowerItsBoundaryTransmits) {
    // Unit sphere of index 1.5, sigma_t 8, a point light of intensity 1 at distance 4.
    const std::vector<VolumeObject> objects = refractingSphere(0.0);
    const VolumeObject& sphere = objects.front();
    const Light light = test::pointLight(Vec3(0.0, 0.0, 4.0), Rgb(1.0));
    // Taken in: the cone of directions from the light that meet the sphere, each
    // transmitted by 1 - R at its incidence (sin i = 4 sin theta).
    double takenIn = 0.0;
    const int steps = 4000;
    const double cone = std::asin(0.25);
    for (int k = 0; k < steps; ++k) {
        const double theta = (k + 0.5) / steps * cone;
        takenIn += 2.0 * kPi * (1.0 - fresnelByAngles(std::asin(std::min(1.0, 4.0 * std::sin(theta))), 1.5)) *
                   std::sin(theta) * cone / steps;
    }
    // Removed: sigma_t times the irradiance through the boundary, attenuated
    // inside, over the volume (midpoint rule in r and the angle to the light's
    // axis; the field is symmetric about it). With sigma_t 8 the shortest chord
    // (1.49) lets e^-12 of it out again.
    double removed = 0.0;
    const int radial = 160, polar = 64;
    for (int a = 0; a < radial; ++a) {
        const double r = (a + 0.5) / radial;
        for (int b = 0; b < polar; ++b) {
            const double theta = (b + 0.5) / polar * kPi;
            const Vec3 x(r * std::sin(theta), 0.0, r * std::cos(theta));
            const std::optional<RefractedArrival> arrival = lightThroughBoundary(sphere, light, x);
            if (!arrival) continue;
            const double attenuation = std::exp(-8.0 * sphere.densityPath(x, arrival->toLight, arrival->inside));
            removed += 8.0 * arrival->irradiance.r * attenuation * 2.0 * kPi * r * r * std::sin(theta) *
                       (1.0 / radial) * (kPi / polar);
        }
    }
    std::printf("taken in %.5f, removed %.5f (%+.2f%%)\n", takenIn, removed, 100.0 * (removed / takenIn - 1.0));
    // Tolerance: the 20480-face sphere and the midpoint rules, 1%.
    EXPECT_NEAR(removed, takenIn, 0.01 * takenIn);
}

// The path tracer skips the solve for the light through the boundary with
// odds below 1 deep inside, and weighs what it finds by their inverse: on a
// unit sphere (n 1.5, sigma_t 8) under a point light on its axis, the mean of
// many draws at each point is the light found without roulette (within four
// standard errors of the draws' binomial spread), and the odds are the
// straight line's transmittance over kSureSolveTransmittance.
TEST(Refraction, RouletteOnTheSolveThroughTheBoundaryKeepsItsMean) {
    const std::vector<VolumeObject> objects = refractingSphere(0.5);
    const VolumeObject& sphere = objects.front();
    const std::vector<Light> lights{test::pointLight(Vec3(0.0, 0.0, 4.0), Rgb(1.0))};
    const Vec3 dir = glm::normalize(Vec3(0.3, -0.2, 1.0));
    // On the axis, 0.2 below the lit pole the straight line keeps e^-1.6 of the light.
    EXPECT_NEAR(boundarySolveOdds(sphere, lights[0], Vec3(0.0, 0.0, 0.8)), std::exp(-1.6) / kSureSolveTransmittance,
                0.01);
    EXPECT_EQ(boundarySolveOdds(sphere, lights[0], Vec3(0.0, 0.0, 0.95)), 1.0);
    Rng rng(7, 0);
    const int draws = 20000;
    for (const Vec3& x : {Vec3(0.0, 0.0, 0.95), Vec3(0.0, 0.0, 0.8), Vec3(0.3, 0.1, 0.0), Vec3(-0.2, 0.4, -0.6)}) {
        const double exact = lightsThroughBoundary(sphere, objects, lights, x, dir).r;
        ASSERT_GT(exact, 0.0);
        const double odds = boundarySolveOdds(sphere, lights[0], x);
        double sum = 0.0;
        int skipped = 0;
        for (int k = 0; k < draws; ++k) {
            const double found =
                lightsThroughBoundaryByRoulette(sphere, objects, lights, x, dir, [&] { return rng.uniform(); }).r;
            sum += found;
            skipped += found == 0.0;
        }
        const double mean = sum / draws, standardError = exact * std::sqrt((1.0 - odds) / (odds * draws));
        std::printf("x (%.2f, %.2f, %.2f): odds %.3f, skipped %d of %d, mean %.6g against %.6g\n", x.x, x.y, x.z, odds,
                    skipped, draws, mean, exact);
        if (odds == 1.0) {
            EXPECT_EQ(skipped, 0);
            EXPECT_NEAR(mean, exact, 1e-12 * exact);
        } else {
            EXPECT_GT(skipped, 0);
            EXPECT_NEAR(mean, exact, 4.0 * standardError);
        }
    }
    EXPECT_EQ(boundarySolveOdds(sphere, lights[0], Vec3(0.3, 0.1, 0.0)), kLeastSolveOdds);
}

// Through a concave boundary (a torus, whose far side of the ring the light
// reaches past, or through, the hole): every solved arrival leaves x by the
// mesh's first crossing along toLight, and there it obeys Snell's law about the
// shading normal, in sines and in the plane of incidence, with the ray out
// heading for the light. Each checked here by its own ray cast and sines, not
// by the solve's own steps: the solve takes its Newton steps on the face its
// current ray leaves by, and must still end on the crossing nearest x.
TEST(Refraction, LightThroughAConcaveBoundaryLeavesByTheFirstCrossingTowardTheLight) {
    constexpr double n = 1.5;
    SceneDesc scene;
    ObjectDesc o = test::simpleObject(test::modelsDir() / "torus.obj", 4.0, 0.5);
    o.medium.ior = n;
    scene.objects = {o};
    std::vector<std::string> warnings;
    const std::vector<VolumeObject> objects = loadObjects(scene, warnings);
    const VolumeObject& torus = objects.front();
    const double diagonal = torus.boundary().bounds().diagonal();
    // Above the ring, level with it (grazing it), in the hole, and far to the side.
    for (const Vec3& position : {Vec3(0.2, 0.9, 0.8), Vec3(0.0, 0.15, 2.0), Vec3(1.5, 0.05, 0.3), Vec3(0.3, 0.3, 0.3),
                                 Vec3(-2.0, 0.4, -1.0)}) {
        const Light light = test::pointLight(position, Rgb(1.0));
        int inside = 0, solved = 0;
        for (int i = 0; i < 40; ++i)
            for (int j = 0; j < 40; ++j)
                for (double y : {-0.1, 0.0, 0.1}) {
                    const Vec3 x(-0.68 + 1.36 * (i + 0.5) / 40, y, -0.68 + 1.36 * (j + 0.5) / 40);
                    if (!torus.contains(x)) continue;
                    ++inside;
                    const std::optional<RefractedArrival> a = lightThroughBoundary(torus, light, x);
                    if (!a) continue;
                    ++solved;
                    const std::optional<BoundaryHit> first = nextBoundaryHit(torus, x, a->toLight);
                    ASSERT_TRUE(first.has_value());
                    EXPECT_NEAR(glm::length(first->point - a->entry), 0.0, 1e-6 * diagonal);
                    EXPECT_NEAR(first->t, a->inside, 1e-6 * diagonal);
                    const Vec3 normal = first->normal;  // outward
                    EXPECT_NEAR(n * glm::length(glm::cross(a->toLight, normal)),
                                glm::length(glm::cross(a->outward, normal)), 1e-6);
                    EXPECT_NEAR(glm::dot(glm::cross(a->toLight, normal), a->outward), 0.0, 1e-6);
                    EXPECT_GT(glm::dot(a->outward, normal), 0.0);
                    EXPECT_NEAR(glm::length(a->outward - glm::normalize(light.position - a->entry)), 0.0, 1e-6);
                }
        std::printf("light at (%.2f, %.2f, %.2f): %d points inside, %d reached by one refraction\n", position.x,
                    position.y, position.z, inside, solved);
        EXPECT_GT(inside, 1000);
        EXPECT_GT(solved, 0);
    }
}

// A half-space of index 1.5 (a box 80 wide and 20 deep) lit by a beam at 30
// degrees and seen at 45 degrees, in perpendicular planes: single scattering
// there has a closed form with Snell's angles, both Fresnel transmissions and
// the 1/n^2 of radiance leaving the medium.
struct HalfSpace {
    static constexpr double n = 1.5, sigmaT = 2.0, albedo = 0.8, g = 0.3;
    const double lightAngle = radians(30.0), viewAngle = radians(45.0);
    SceneDesc scene;
    Vec3 eye;

    explicit HalfSpace(test::ScratchDir& dir) {
        ObjectDesc o =
            test::simpleObject(test::writeBox(dir, "half.obj", Vec3(-40, -40, -20), Vec3(40, 40, 0)), sigmaT, albedo);
        o.medium.ior = n;
        o.medium.g = g;
        scene.objects = {o};
        Light beam;
        beam.type = Light::Type::Directional;
        beam.direction = Vec3(std::sin(lightAngle), 0.0, -std::cos(lightAngle));
        beam.power = Rgb(kPi);
        scene.lights = {beam};
        eye = 10.0 * Vec3(0.0, std::sin(viewAngle), std::cos(viewAngle));
        scene.camera.position = eye;
        scene.camera.target = Vec3(0.0);
        scene.camera.up = Vec3(1, 0, 0);
    }
    // Inside: the beam along t_l, the view ray along t_v (Snell), the phase at their angle.
    double closedForm() const {
        const double cosLight = std::cos(std::asin(std::sin(lightAngle) / n));
        const double cosView = std::cos(std::asin(std::sin(viewAngle) / n));
        const double cosScatter = -cosLight * cosView;  // t_l . (-t_v): both go down, in perpendicular planes
        const double phase = (1.0 - g * g) / (4.0 * kPi * std::pow(1.0 + g * g - 2.0 * g * cosScatter, 1.5));
        const double irradianceInside = kPi * std::cos(lightAngle) * (1.0 - fresnelByAngles(lightAngle, n)) / cosLight;
        const double radianceInside = albedo * phase * irradianceInside / (1.0 + cosView / cosLight);
        return (1.0 - fresnelByAngles(viewAngle, n)) / (n * n) * radianceInside;
    }
};

TEST(Refraction, HalfSpaceSingleScatteringIsTheClosedForm) {
    test::ScratchDir dir;
    const HalfSpace half(dir);
    PathSettings settings;
    settings.samplesPerPixel = 20000;
    settings.maxScatter = 1;
    const test::SpotRadiance spot = test::spotRadiance(half.scene, settings);
    const double mean = spot.mean, expected = half.closedForm();
    const double standardError = spot.standardError;
    std::printf("radiance %.6g +- %.2g (expected %.6g, %+.2f%%)\n", mean, standardError, expected,
                100.0 * (mean / expected - 1.0));
    EXPECT_NEAR(mean, expected, std::max(3.0 * standardError, 0.005 * expected));
}

// The single-scattering reference refracts too: on the same half-space its
// radiance for the central pixel is the closed form, without the path
// tracer's noise (tolerance: the quadrature's 1e-5 and the box's far faces,
// 40 optical depths away).
TEST(Refraction, ReferenceOnTheHalfSpaceIsTheClosedForm) {
    test::ScratchDir dir;
    const HalfSpace half(dir);
    std::vector<std::string> warnings;
    const std::vector<VolumeObject> objects = loadObjects(half.scene, warnings);
    ReferenceSettings settings;
    settings.tolerance = 1e-5;
    const double radiance =
        ReferenceRenderer(half.scene, objects).radiance(half.eye, glm::normalize(-half.eye), settings).r;
    const double expected = half.closedForm();
    std::printf("reference %.8g, closed form %.8g (%+.4f%%)\n", radiance, expected,
                100.0 * (radiance / expected - 1.0));
    EXPECT_NEAR(radiance, expected, 1e-3 * expected);
}

// On a refracting sphere (ior 1.33 and 1.5, internal reflections, total
// internal reflection near the rim, light found through the boundary) the
// reference is what `--method path --max-scatter 1` converges to: the images'
// totals agree within 3 standard errors of the path tracer's, and so do the
// brightest pixels one by one.
TEST(Refraction, ReferenceIsThePathTracersSingleScatteringOnASphere) {
    for (const double n : {1.33, 1.5}) {
        SCOPED_TRACE(n);
        SceneDesc scene;
        scene.camera = test::squareCamera(Vec3(0, 0, 5), Vec3(0), 30, 10);
        scene.lights = {test::pointLight(Vec3(3, 3, 3), Rgb(40.0))};
        scene.objects = {test::simpleObject(test::modelsDir() / "sphere.obj", 2.0, 0.75)};
        scene.objects[0].medium.ior = n;
        scene.objects[0].medium.g = 0.3;
        std::vector<std::string> warnings;
        const std::vector<VolumeObject> objects = loadObjects(scene, warnings);
        ReferenceSettings exact;
        exact.surface = false;
        const Image reference = ReferenceRenderer(scene, objects).render(exact);
        PathSettings paths;
        paths.samplesPerPixel = 3000;
        paths.maxScatter = 1;
        paths.surface = false;
        const PathTracer::Result path = PathTracer(scene, objects).render(paths);
        double sumReference = 0.0, sumPath = 0.0, variance = 0.0;
        int far = 0, bright = 0;
        double peak = 0.0;
        for (const glm::vec3& p : reference.pixels) peak = std::max(peak, double(p.g));
        for (size_t i = 0; i < reference.pixels.size(); ++i) {
            const double r = reference.pixels[i].g, m = path.mean.pixels[i].g, se = path.standardError.pixels[i].g;
            sumReference += r, sumPath += m, variance += se * se;
            if (r < 0.2 * peak) continue;
            ++bright;
            far += std::abs(r - m) > 3.5 * se + 1e-3 * r ? 1 : 0;
        }
        std::printf(
            "ior %.2f: reference total %.6g, path %.6g +- %.2g (%+.2f%%); %d of %d bright pixels beyond 3.5 "
            "standard errors\n",
            n, sumReference, sumPath, std::sqrt(variance), 100.0 * (sumReference / sumPath - 1.0), far, bright);
        EXPECT_NEAR(sumReference, sumPath, 3.0 * std::sqrt(variance) + 2e-3 * sumPath);
        EXPECT_GT(bright, 15);
        EXPECT_LE(far, std::max(1, bright / 50));
    }
}

}  // namespace
}  // namespace lucent
