// The view and the light through a refracting boundary (runtime/internal/
// refracted_view.h, traced_light.h) on a box, against what is worked out here
// from the flat faces: Snell's law, Fresnel's equations in their angle form
// (Born and Wolf, Principles of Optics, 1.5.3), the n^2 law of radiance, the
// reflection back inside where the refracted ray leaves (the same form, from
// inside, and total past the critical angle), the compression of a parallel
// beam (its irradiance times cos i / cos t) and the paraxial image of a point
// light under a flat boundary. No GL context.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/volume_object.h"
#include "runtime/internal/refracted_view.h"
#include "runtime/internal/traced_light.h"
#include "tests/support/test_support.h"

namespace lucent {
namespace {

constexpr double kIor = 1.5;

// Unpolarised Fresnel reflectance from the angles of incidence i and refraction t.
double angleFormReflectance(double i, double t) {
    if (i < 1e-6) return std::pow((kIor - 1.0) / (kIor + 1.0), 2);
    const double s = std::sin(i - t) / std::sin(i + t), p = std::tan(i - t) / std::tan(i + t);
    return 0.5 * (s * s + p * p);
}

struct Box {
    Box() {
        ObjectDesc desc = test::simpleObject(test::writeBox(dir, "box.obj", Vec3(-1.0), Vec3(1.0)), 1.0);
        desc.medium.ior = kIor;
        std::vector<std::string> warnings;
        volume = std::make_unique<VolumeObject>(desc, warnings);
    }
    test::ScratchDir dir;
    std::unique_ptr<VolumeObject> volume;
};

// Where the ray from o along unit d first meets [-1, 1]^3 (t < 0: never), with the face's outward normal.
double enterBox(const Vec3& o, const Vec3& d, Vec3& normal) {
    double near = -1e30, far = 1e30;
    for (int k = 0; k < 3; ++k) {
        const double a = (-1.0 - o[k]) / d[k], b = (1.0 - o[k]) / d[k];
        if (std::min(a, b) > near) {
            near = std::min(a, b);
            normal = Vec3(0.0);
            normal[k] = d[k] > 0.0 ? -1.0 : 1.0;
        }
        far = std::min(far, std::max(a, b));
    }
    return near <= far && near > 0.0 ? near : -1.0;
}

// How far the ray from p (inside) along d goes before it leaves [-1, 1]^3.
double leaveBox(const Vec3& p, const Vec3& d) {
    double t = 1e30;
    for (int k = 0; k < 3; ++k) t = std::min(t, ((d[k] > 0.0 ? 1.0 : -1.0) - p[k]) / d[k]);
    return t;
}

TEST(RefractedView, EachPixelsRayObeysSnellFresnelAndTheBox) {
    Box box;
    Camera camera = test::squareCamera(Vec3(3.0, 2.0, 5.0), Vec3(0.0), 30, 24);
    const ViewSetup view = viewSetupFor(camera, box.volume->mesh().bounds());
    const std::vector<RefractedStretch> rays = refractedViewRays(*box.volume, Similarity{}, view);
    constexpr size_t K = gpu::kRefractedStretches;
    ASSERT_EQ(rays.size(), 24u * 24u * K);
    // The pixel's ray by unprojecting its centre at two depths.
    const glm::dmat4 toWorld = glm::inverse(glm::dmat4(view.projection) * glm::dmat4(view.view));
    int inside = 0;
    for (int y = 0; y < 24; ++y)
        for (int x = 0; x < 24; ++x) {
            const RefractedStretch& got = rays[size_t(y * 24 + x) * K];
            const RefractedStretch& reflected = rays[size_t(y * 24 + x) * K + 1];
            const glm::dvec2 ndc((x + 0.5) / 12.0 - 1.0, (y + 0.5) / 12.0 - 1.0);
            const glm::dvec4 a = toWorld * glm::dvec4(ndc, -0.5, 1.0), b = toWorld * glm::dvec4(ndc, 0.5, 1.0);
            const Vec3 origin(view.cameraPosition);
            const Vec3 d = glm::normalize(Vec3(b) / b.w - Vec3(a) / a.w);
            Vec3 n(0.0);
            const double t = enterBox(origin, d, n);
            if (t < 0.0) {
                EXPECT_EQ(got.origin.w, 0.0f) << "pixel " << x << ", " << y << " misses the box";
                EXPECT_EQ(reflected.origin.w, 0.0f);
                continue;
            }
            ++inside;
            const double i = std::acos(-glm::dot(d, n)), r = std::asin(std::sin(i) / kIor);
            const Vec3 along = glm::normalize(d - glm::dot(d, n) * n);  // the tangent the ray bends in
            const Vec3 bent = std::sin(r) * (std::abs(std::sin(i)) > 1e-12 ? along : Vec3(0.0)) - std::cos(r) * n;
            const Vec3 entry = origin + t * d;
            const glm::dmat4 toView(view.view);
            const Vec3 entryView(toView * glm::dvec4(entry, 1.0)), bentView(glm::dmat3(toView) * bent);
            for (int k = 0; k < 3; ++k) {
                EXPECT_NEAR(got.origin[k], entryView[k], 1e-4) << "entry, pixel " << x << ", " << y;
                EXPECT_NEAR(got.direction[k], bentView[k], 1e-5) << "direction, pixel " << x << ", " << y;
            }
            const double weight = (1.0 - angleFormReflectance(i, r)) / (kIor * kIor);
            EXPECT_NEAR(got.origin.w, weight, 1e-6);
            const double length = leaveBox(entry, bent);
            EXPECT_NEAR(got.direction.w, length, 1e-4);
            // Reflected back inside where it leaves: about the face it meets there.
            const Vec3 exit = entry + length * bent;
            Vec3 face(0.0);
            for (int k = 0; k < 3; ++k)
                if (std::abs(std::abs(exit[k]) - 1.0) < 1e-9) face[k] = exit[k] > 0.0 ? 1.0 : -1.0;
            if (glm::length(face) != 1.0) continue;                // through an edge: either face's normal
            const double inner = std::acos(glm::dot(bent, face));  // incidence inside
            const double sinOut = kIor * std::sin(inner);
            const double share = sinOut >= 1.0 ? 1.0 : angleFormReflectance(std::asin(sinOut), inner);
            const Vec3 mirrored = bent - 2.0 * glm::dot(bent, face) * face;
            const Vec3 exitView(toView * glm::dvec4(exit, 1.0)), mirroredView(glm::dmat3(toView) * mirrored);
            EXPECT_NEAR(reflected.origin.w, weight * share, 1e-6) << "pixel " << x << ", " << y;
            for (int k = 0; k < 3; ++k) {
                EXPECT_NEAR(reflected.origin[k], exitView[k], 1e-4) << "exit, pixel " << x << ", " << y;
                EXPECT_NEAR(reflected.direction[k], mirroredView[k], 1e-5) << "mirrored, pixel " << x << ", " << y;
            }
            EXPECT_NEAR(reflected.direction.w, leaveBox(exit, mirrored), 1e-4);
        }
    EXPECT_GT(inside, 100) << "the box fills much of the view";
}

TEST(TracedLight, ABeamBendsInAndIsCompressedByTheBoundary) {
    Box box;
    // Travelling down and along +x, it meets the top face at cos i = 0.8.
    Light sun;
    sun.type = Light::Type::Directional;
    sun.direction = Vec3(0.6, -0.8, 0.0);
    sun.power = Rgb(1.0);
    const double i = std::acos(0.8), t = std::asin(0.6 / kIor);
    // The renderer stands the box twice as large: every length inside doubles.
    const Similarity twice = makeSimilarity(2.0, Vec3(0.0, 0.0, 1.0), 0.0, Vec3(0.0));
    for (const Similarity& placement : {Similarity{}, twice}) {
        SampleSet samples;
        samples.positions = {glm::vec3(0.0f, 0.2f, 0.1f)};
        const std::vector<glm::vec4> r = tracedRefractedLight({{box.volume.get(), placement}}, 0, samples, {sun});
        ASSERT_EQ(r.size(), 2u);
        // 0.8 below the top face (in the box's units), along the refracted ray.
        const double depth = placement.scale * 0.8 / std::cos(t);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(r[0][c], depth, 1e-5) << "optical depth at sigma_t 1";
        EXPECT_EQ(r[0].w, 0.0f);
        EXPECT_NEAR(r[1].x, -std::sin(t), 1e-6);
        EXPECT_NEAR(r[1].y, std::cos(t), 1e-6);
        EXPECT_NEAR(r[1].z, 0.0, 1e-6);
        EXPECT_NEAR(r[1].w, (1.0 - angleFormReflectance(i, t)) * std::cos(i) / std::cos(t), 1e-4)
            << "the beam's transmission and compression";
    }
}

TEST(TracedLight, APointLightIsSeenAtItsParaxialImage) {
    Box box;
    // Straight above the sample: under a flat boundary a point light h above
    // it, seen from d below, spreads as if it stood h + d / n away.
    const Light light = test::pointLight(Vec3(0.0, 3.0, 0.0), Rgb(1.0));
    const double normal = 1.0 - std::pow((kIor - 1.0) / (kIor + 1.0), 2);
    SampleSet samples;
    samples.positions = {glm::vec3(0.0f)};
    // As the box stands (h 2, d 1), and twice as large about the origin in the renderer (h 1, d 2).
    const Similarity twice = makeSimilarity(2.0, Vec3(0.0, 0.0, 1.0), 0.0, Vec3(0.0));
    const double expected[2] = {normal / std::pow(2.0 + 1.0 / kIor, 2), normal / std::pow(1.0 + 2.0 / kIor, 2)};
    int k = 0;
    for (const Similarity& placement : {Similarity{}, twice}) {
        const std::vector<glm::vec4> r = tracedRefractedLight({{box.volume.get(), placement}}, 0, samples, {light});
        ASSERT_EQ(r.size(), 2u);
        EXPECT_NEAR(r[0].x, placement.scale, 1e-5) << "1 inside the box's own units";
        EXPECT_NEAR(r[1].y, 1.0, 1e-9);
        EXPECT_NEAR(r[1].w, expected[k], 1e-4 * expected[k]) << "placement scale " << placement.scale;
        ++k;
    }
}

}  // namespace
}  // namespace lucent
