#include "core/surface_shape.h"

#include <gtest/gtest.h>

#include <functional>

namespace lucent {
namespace {

// A closed mesh from a map of [0, 1]^2: rings along v from pole to pole
// (wrapU only) or a torus's grid (wrapping both ways).
TriangleMesh gridMesh(int nu, int nv, bool torus, const std::function<Vec3(double, double)>& at) {
    std::vector<Vec3> p;
    std::vector<std::array<uint32_t, 3>> t;
    const int rings = torus ? nv : nv - 1;  // a sphere's inner rings; its poles come last
    for (int j = 0; j < rings; ++j)
        for (int i = 0; i < nu; ++i) p.push_back(at(double(i) / nu, torus ? double(j) / nv : double(j + 1) / nv));
    const auto id = [&](int i, int j) { return uint32_t((j % rings) * nu + (i % nu)); };
    for (int j = 0; j + 1 < rings + (torus ? 1 : 0); ++j)
        for (int i = 0; i < nu; ++i) {
            t.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
            t.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
        }
    if (!torus) {
        const auto south = uint32_t(p.size()), north = south + 1;
        p.push_back(at(0.0, 0.0));
        p.push_back(at(0.0, 1.0));
        for (int i = 0; i < nu; ++i) {
            t.push_back({south, id(i + 1, 0), id(i, 0)});
            t.push_back({north, id(i, rings - 1), id(i + 1, rings - 1)});
        }
    }
    std::vector<std::string> warnings;
    return closedMesh(p, t, "grid", warnings);
}

Vec3 onSphere(double u, double v) {
    const double phi = 2.0 * kPi * u, theta = kPi * v;
    return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), -std::cos(theta)};
}

TriangleMesh cube() {
    std::vector<Vec3> p;
    for (int k = 0; k < 8; ++k) p.push_back({k & 1 ? 1.0 : -1.0, k & 2 ? 1.0 : -1.0, k & 4 ? 1.0 : -1.0});
    const std::vector<std::array<uint32_t, 3>> t = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                                                    {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
    std::vector<std::string> warnings;
    return closedMesh(p, t, "cube", warnings);
}

TEST(SurfaceShape, ATessellatedSphereIsSmoothAndConvex) {
    const SurfaceShape s = surfaceShape(gridMesh(64, 32, false, onSphere));
    EXPECT_TRUE(s.convex);
    // Neighbouring rings' normals differ by about 180 / 32 degrees, segments by 360 / 64.
    EXPECT_GT(s.sharpestDegrees, 5.0);
    EXPECT_LT(s.sharpestDegrees, 12.0);
    EXPECT_LT(s.largestFlatShare, 0.005);
    EXPECT_TRUE(smoothConvex(s));
}

TEST(SurfaceShape, AnEllipsoidAndACapsuleAreSmoothAndConvex) {
    const auto ellipsoid = [](double u, double v) { return onSphere(u, v) * Vec3(3.0, 1.8, 2.2); };
    EXPECT_TRUE(smoothConvex(surfaceShape(gridMesh(96, 48, false, ellipsoid))));
    // Two hemispheres joined by a cylinder: its quads are flat, each a 64th of its round.
    const auto capsule = [](double u, double v) { return onSphere(u, v) + Vec3(0.0, 0.0, v < 0.5 ? -1.4 : 1.4); };
    const SurfaceShape c = surfaceShape(gridMesh(64, 33, false, capsule));
    EXPECT_TRUE(c.convex);
    EXPECT_GT(c.largestFlatShare, 0.0);
    EXPECT_TRUE(smoothConvex(c));
}

TEST(SurfaceShape, ACubeHasFlatFacesAndCreases) {
    const SurfaceShape s = surfaceShape(cube());
    EXPECT_TRUE(s.convex);
    EXPECT_NEAR(s.sharpestDegrees, 90.0, 1e-9);
    EXPECT_NEAR(s.largestFlatShare, 1.0 / 6.0, 1e-12);  // each face is one patch of its two triangles
    EXPECT_FALSE(smoothConvex(s));
}

TEST(SurfaceShape, ATorusIsNotConvex) {
    const auto torus = [](double u, double v) {
        const double phi = 2.0 * kPi * u, theta = 2.0 * kPi * v;
        return Vec3((2.0 + 0.6 * std::cos(theta)) * std::cos(phi), (2.0 + 0.6 * std::cos(theta)) * std::sin(phi),
                    0.6 * std::sin(theta));
    };
    const SurfaceShape s = surfaceShape(gridMesh(64, 32, true, torus));
    EXPECT_FALSE(s.convex);
    EXPECT_LT(s.sharpestDegrees, 12.0);  // smooth, but bent inwards where it faces its hole
    EXPECT_FALSE(smoothConvex(s));
}

TEST(SurfaceShape, AHemisphereHasACreaseAndAFlatFace) {
    // The lower half of a sphere, its equator closed by a flat disc to the north pole's place at the centre.
    const auto dome = [](double u, double v) { return v <= 0.5 ? onSphere(u, v) : onSphere(u, 0.5) * (2.0 - 2.0 * v); };
    const SurfaceShape s = surfaceShape(gridMesh(64, 32, false, dome));
    EXPECT_TRUE(s.convex);
    EXPECT_NEAR(s.sharpestDegrees, 90.0, 6.0);
    EXPECT_GT(s.largestFlatShare, 0.3);  // the disc: pi of the 3 pi of the whole
    EXPECT_FALSE(smoothConvex(s));
}

}  // namespace
}  // namespace lucent
