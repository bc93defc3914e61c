// Optical depth along rays: every crossing of a concave or multi-part boundary,
// and blockers that stop light. Expected values are closed-form chord lengths.
#include <gtest/gtest.h>

#include <algorithm>

#include "core/error.h"
#include "core/rng.h"
#include "core/volume_object.h"
#include "tests/support/test_support.h"

namespace lucent {
namespace {

std::string boxObj(Vec3 lo, Vec3 hi, int firstIndex = 1) {
    std::string s;
    for (int i = 0; i < 8; ++i) {
        const Vec3 p((i & 4) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 1) ? hi.z : lo.z);
        s += "v " + std::to_string(p.x) + " " + std::to_string(p.y) + " " + std::to_string(p.z) + "\n";
    }
    const int quads[6][4] = {{0, 1, 3, 2}, {4, 6, 7, 5}, {0, 4, 5, 1}, {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 5, 7, 3}};
    for (const auto& q : quads) {
        auto v = [&](int k) { return std::to_string(q[k] + firstIndex); };
        s += "f " + v(0) + " " + v(1) + " " + v(2) + "\nf " + v(0) + " " + v(2) + " " + v(3) + "\n";
    }
    return s;
}

TEST(OpticalDepth, CrossesEveryPartOfTheBoundary) {
    test::ScratchDir dir;
    // Two separate boxes: a ray from inside the first leaves it, crosses the gap and the second.
    const auto mesh = dir.write("two.obj", boxObj(Vec3(-2, -0.5, -0.5), Vec3(-1, 0.5, 0.5)) +
                                               boxObj(Vec3(1, -0.5, -0.5), Vec3(2, 0.5, 0.5), 9));
    std::vector<std::string> warnings;
    const VolumeObject object(test::simpleObject(mesh, 1.0), warnings);
    const Vec3 start(-1.5, 0.1, 0.2);
    const Vec3 dir3 = glm::normalize(Vec3(1, 0.05, -0.03));
    // Inside for x in [-1.5, -1] and [1, 2]: 1.5 units of x, scaled by 1 / dir.x.
    EXPECT_NEAR(object.densityPath(start, dir3), 1.5 / dir3.x, 1e-9);
    EXPECT_NEAR(object.densityPath(start, dir3, 3.0 / dir3.x), 0.5 / dir3.x + 0.5 / dir3.x, 1e-9);
    EXPECT_NEAR(object.densityPath(start, -dir3), 0.5 / dir3.x, 1e-9);
}

TEST(OpticalDepth, ConcaveTorusThroughVertices) {
    // The bundled torus (radii 0.5 and 0.18, vertices exactly on the x axis): a ray
    // along +x from the tube centre at x = -0.5 is inside on [-0.5, -0.32] and [0.32, 0.68].
    std::vector<std::string> warnings;
    const VolumeObject torus(test::simpleObject(test::modelsDir() / "torus.obj", 1.0), warnings);
    EXPECT_NEAR(torus.densityPath(Vec3(-0.5, 0, 0), Vec3(1, 0, 0)), 0.18 + 0.36,
                1e-6);  // OpenMesh reads coordinates as float
    EXPECT_NEAR(torus.densityPath(Vec3(-0.9, 0, 0), Vec3(1, 0, 0)), 0.36 + 0.36, 1e-6);
    EXPECT_DOUBLE_EQ(torus.densityPath(Vec3(0, 0, 0), Vec3(0, 1, 0)), 0.0);
}

TEST(OpticalDepth, FirstCrossingIsTheFirstOfAllCrossingsBetweenItsEnds) {
    // The one-traversal query against the collecting one, on the concave torus,
    // from points inside, outside and on the surface itself (where single
    // precision may report the face the ray starts on).
    std::vector<std::string> warnings;
    const VolumeObject torus(test::simpleObject(test::modelsDir() / "torus.obj", 1.0), warnings);
    const MeshRaycaster& caster = torus.boundary();
    Rng rng(3, 4);
    std::vector<Crossing> all;
    int onSurface = 0;
    for (int i = 0; i < 2000; ++i) {
        Vec3 x = 1.6 * (Vec3(rng.uniform(), rng.uniform(), rng.uniform()) - 0.5);
        const Vec3 w = glm::normalize(Vec3(rng.uniform(), rng.uniform(), rng.uniform()) - 0.5);
        const double tMin = 1e-7;
        if (i % 2 == 1) {  // start on the surface: where a ray from x meets it
            caster.crossings(x, w, all);
            if (all.empty()) continue;
            x += all.front().t * w;
            ++onSurface;
        }
        caster.crossings(x, w, all);
        const auto expected = std::find_if(all.begin(), all.end(), [&](const Crossing& c) { return c.t > tMin; });
        const std::optional<Crossing> first = caster.firstCrossing(x, w, tMin);
        ASSERT_EQ(first.has_value(), expected != all.end()) << i;
        if (!first) continue;
        EXPECT_NEAR(first->t, expected->t, 1e-9) << i;
        EXPECT_EQ(first->exits, expected->exits) << i;
        // Bounded at tMax, a hand's breadth in double precision before or after the
        // crossing (single precision alone cannot tell them apart).
        const double gap = 1e-9 * (1.0 + expected->t);
        EXPECT_FALSE(caster.firstCrossing(x, w, tMin, expected->t - gap)) << i;
        const std::optional<Crossing> within = caster.firstCrossing(x, w, tMin, expected->t + gap);
        ASSERT_TRUE(within) << i;
        EXPECT_NEAR(within->t, expected->t, 1e-9) << i;
    }
    EXPECT_GT(onSurface, 150);  // 227 of the 1000 odd rays meet the torus
}

TEST(OpticalDepth, SphereChordsMatchTheCircle) {
    std::vector<std::string> warnings;
    const VolumeObject sphere(test::simpleObject(test::modelsDir() / "sphere.obj", 1.0), warnings);
    Rng rng(9, 9);
    for (int i = 0; i < 100; ++i) {
        const Vec3 x = 0.8 * (Vec3(rng.uniform(), rng.uniform(), rng.uniform()) - 0.5);
        const Vec3 w = glm::normalize(Vec3(rng.uniform(), rng.uniform(), rng.uniform()) - 0.5);
        const double b = glm::dot(x, w), c = glm::dot(x, x) - 1.0;
        const double exact = -b + std::sqrt(b * b - c);
        // The icosphere sits inside the unit sphere by at most its sagitta (~2e-4).
        EXPECT_NEAR(sphere.densityPath(x, w), exact, 1e-3);
    }
}

TEST(OpticalDepth, BlockerStopsLight) {
    test::ScratchDir dir;
    const auto outer = dir.write("outer.obj", boxObj(Vec3(-1), Vec3(1)));
    const auto inner = dir.write("inner.obj", boxObj(Vec3(-0.2), Vec3(0.2)));
    ObjectDesc desc = test::simpleObject(outer, 2.0);
    desc.medium.blockers = {inner};
    std::vector<std::string> warnings;
    const VolumeObject object(desc, warnings);
    EXPECT_EQ(object.densityPath(Vec3(-0.8, 0, 0), Vec3(1, 0, 0)), kInfinity);
    EXPECT_NEAR(object.densityPath(Vec3(-0.8, 0.5, 0), Vec3(1, 0, 0)), 1.8, 1e-9);
    EXPECT_TRUE(object.insideBlocker(Vec3(0.1, 0, 0)));
    EXPECT_EQ(object.extinction(Vec3(0.1, 0, 0)), Rgb(0.0));
    EXPECT_EQ(object.extinction(Vec3(0.5, 0, 0)), Rgb(2.0));
    // Transmittance through a blocker is exactly 0, even for sigma_t = 0.
    EXPECT_EQ(transmittance(Rgb(0.0), kInfinity), Rgb(0.0));
}

TEST(OpticalDepth, BlockerOutsideItsObjectIsAnError) {
    test::ScratchDir dir;
    const auto outer = dir.write("outer.obj", boxObj(Vec3(-1), Vec3(1)));
    const auto stray = dir.write("stray.obj", boxObj(Vec3(0.5), Vec3(1.5)));
    ObjectDesc desc = test::simpleObject(outer, 2.0);
    desc.medium.blockers = {stray};
    std::vector<std::string> warnings;
    try {
        VolumeObject object(desc, warnings);
        FAIL();
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("stray.obj: blocker is not inside its object"), std::string::npos);
    }
}

TEST(OpticalDepth, LayeredMediumAlongTheAxis) {
    ObjectDesc desc = test::simpleObject(test::modelsDir() / "cube.obj", 1.0);
    desc.medium.density.type = DensityDesc::Type::Layers;
    desc.medium.density.axis = 2;
    desc.medium.density.values = {1.0, 3.0};
    std::vector<std::string> warnings;
    const VolumeObject cube(desc, warnings);
    // From z = -0.5 up: 0.5 in density 1, then 1 in density 3.
    EXPECT_NEAR(cube.densityPath(Vec3(0.1, 0.2, -0.5), Vec3(0, 0, 1)), 0.5 + 3.0, 1e-9);
}

}  // namespace
}  // namespace lucent

namespace lucent {
namespace {

// Rays from an eye outside a box, aimed at points on its edges and corners: in
// single precision some report only one of the two faces they graze. The parts
// inside must still lie between the box's near and far planes, never run back
// to the eye (a lone exit once made the whole stretch from the eye count).
TEST(OpticalDepth, RaysGrazingEdgesKeepTheirParity) {
    test::ScratchDir dir;
    const auto mesh = dir.write("box.obj", boxObj(Vec3(-1), Vec3(1)));
    std::vector<std::string> warnings;
    const VolumeObject box(test::simpleObject(mesh, 1.0), warnings);
    const Vec3 eye(3.5, 2.0, 4.5);
    std::vector<Interval> inside;
    Rng rng(7, 0);
    int grazing = 0;
    for (int i = 0; i < 20000; ++i) {
        // A point on one of the 12 edges.
        Vec3 p(2.0 * rng.uniform() - 1.0);
        const int axis = i % 3;
        const int corner = (i / 3) % 4;
        p[(axis + 1) % 3] = (corner & 1) ? 1.0 : -1.0;
        p[(axis + 2) % 3] = (corner & 2) ? 1.0 : -1.0;
        const Vec3 d = glm::normalize(p - eye);
        box.boundary().insideIntervals(eye, d, kInfinity, inside, false);
        double length = 0.0;
        for (const Interval& s : inside) {
            EXPECT_GT(s.t0, 0.5) << "ray " << i;
            length += s.t1 - s.t0;
        }
        EXPECT_LE(length, 2.0 * std::sqrt(3.0) + 1e-6) << "ray " << i;
        grazing += inside.empty() ? 1 : 0;
    }
    EXPECT_GT(grazing, 0);  // some do graze
}

}  // namespace
}  // namespace lucent

namespace lucent {
namespace {

// Packets of parallel rays from neighbouring points (the SH projection's): each
// ray's path is the circle's chord, and the same as the ray traced alone.
TEST(OpticalDepth, PacketsOfParallelRaysMatchTheCircleAndEachRayAlone) {
    std::vector<std::string> warnings;
    const VolumeObject sphere(test::simpleObject(test::modelsDir() / "sphere.obj", 1.0), warnings);
    const VolumeObject torus(test::simpleObject(test::modelsDir() / "torus.obj", 1.0), warnings);
    Rng rng(5, 2);
    for (int packet = 0; packet < 40; ++packet) {
        const size_t count = 1 + size_t(packet) % MeshRaycaster::kPacket;  // short packets too
        const Vec3 w = glm::normalize(Vec3(rng.uniform(), rng.uniform(), rng.uniform()) - 0.5);
        const Vec3 centre = 0.8 * (Vec3(rng.uniform(), rng.uniform(), rng.uniform()) - 0.5);
        std::vector<Vec3> origins(count), dirs(count, w);
        for (Vec3& x : origins) x = centre + 0.05 * (Vec3(rng.uniform(), rng.uniform(), rng.uniform()) - 0.5);
        std::vector<double> paths(count);
        sphere.densityPaths(origins, dirs, true, paths);
        for (size_t k = 0; k < count; ++k) {
            const double b = glm::dot(origins[k], w), c = glm::dot(origins[k], origins[k]) - 1.0;
            EXPECT_NEAR(paths[k], -b + std::sqrt(b * b - c), 1e-3);  // the icosphere's sagitta
            EXPECT_DOUBLE_EQ(paths[k], sphere.densityPath(origins[k], w));
        }
        // The torus is crossed up to four times, and rays from outside start there.
        for (Vec3& x : origins) x *= 1.5;
        torus.densityPaths(origins, dirs, true, paths);
        for (size_t k = 0; k < count; ++k) EXPECT_DOUBLE_EQ(paths[k], torus.densityPath(origins[k], w)) << k;
    }
}

TEST(OpticalDepth, APacketSeesBlockersUnlessItLooksThroughThem) {
    test::ScratchDir dir;
    ObjectDesc desc = test::simpleObject(dir.write("outer.obj", boxObj(Vec3(-1), Vec3(1))), 2.0);
    desc.medium.blockers = {dir.write("inner.obj", boxObj(Vec3(-0.2), Vec3(0.2)))};
    std::vector<std::string> warnings;
    const VolumeObject object(desc, warnings);
    const std::vector<Vec3> origins = {Vec3(-0.8, 0, 0), Vec3(-0.8, 0.5, 0)}, dirs(2, Vec3(1, 0, 0));
    std::vector<double> paths(2);
    object.densityPaths(origins, dirs, false, paths);
    EXPECT_EQ(paths[0], kInfinity);
    EXPECT_NEAR(paths[1], 1.8, 1e-9);
    object.densityPaths(origins, dirs, true, paths);
    EXPECT_NEAR(paths[0], 1.8, 1e-9);  // the blocker filled by the medium
    EXPECT_NEAR(paths[1], 1.8, 1e-9);
}

// Closest points against closed forms: the cube's (faces, edges and corners,
// from inside and outside) and the sphere's, whose 20480 faces only a search
// that culls right finds the nearest of.
TEST(ClosestPoint, CubeAndSphereInClosedForm) {
    std::vector<std::string> warnings;
    const VolumeObject cube(test::simpleObject(test::modelsDir() / "cube.obj", 1.0), warnings);
    const VolumeObject sphere(test::simpleObject(test::modelsDir() / "sphere.obj", 1.0), warnings);
    Rng rng(11, 3);
    for (int i = 0; i < 2000; ++i) {
        const Vec3 p = 3.0 * (Vec3(rng.uniform(), rng.uniform(), rng.uniform()) - 0.5);
        Vec3 expected = glm::clamp(p, Vec3(-1.0), Vec3(1.0));
        if (expected == p) {  // inside: straight to the face with the least slack
            int axis = 0;
            for (int a = 1; a < 3; ++a)
                if (1.0 - std::abs(p[a]) < 1.0 - std::abs(p[axis])) axis = a;
            expected[axis] = p[axis] < 0.0 ? -1.0 : 1.0;
        }
        const Vec3 got = cube.boundary().closestPoint(p);
        EXPECT_LT(glm::length(got - expected), 1e-12) << i;
        // The icosphere lies between the unit sphere and its sagitta (~2e-4) inside it.
        EXPECT_NEAR(sphere.boundary().distanceToSurface(p), std::abs(glm::length(p) - 1.0), 5e-4) << i;
    }
    EXPECT_LT(glm::length(sphere.boundary().closestPoint(Vec3(40, 0, 0)) - Vec3(1, 0, 0)), 1e-3);
}

// A bound on the distance only speeds the search: with a true bound (the
// distance to any surface point) and with one too small, the same point.
TEST(ClosestPoint, ABoundChangesNothingButTheSearch) {
    std::vector<std::string> warnings;
    const VolumeObject sphere(test::simpleObject(test::modelsDir() / "sphere.obj", 1.0), warnings);
    const MeshRaycaster& boundary = sphere.boundary();
    Rng rng(12, 5);
    for (int i = 0; i < 500; ++i) {
        const Vec3 p = 2.4 * (Vec3(rng.uniform(), rng.uniform(), rng.uniform()) - 0.5);
        const Vec3 exact = boundary.closestPoint(p);
        const Vec3 elsewhere = boundary.closestPoint(p + Vec3(0.05, -0.03, 0.02));
        EXPECT_EQ(boundary.closestPoint(p, glm::length(elsewhere - p)), exact) << i;
        EXPECT_EQ(boundary.closestPoint(p, 0.1 * glm::length(exact - p)), exact) << i;
    }
}

}  // namespace
}  // namespace lucent
