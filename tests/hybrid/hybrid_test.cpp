// The hybrid's parts on the OpenCL device (PoCL here), each against an
// independent truth: the eikonal march against the analytic ray in a linear
// index gradient and Snell's law; the photon and lattice energy balances; the
// spread of a point source against the persistent random walk the collision
// matrix defines; the blocked lattice against the global one.
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "hybrid/internal/cl_device.h"
#include "hybrid/internal/lattice.h"
#include "hybrid/internal/photon_marcher.h"
#include "hybrid/multiple_scattering.h"
#include "hybrid/photon_rays.h"
#include "hybrid/voxelisation.h"
#include "tests/support/test_support.h"

namespace lucent::hybrid {
namespace {

using clshared::PhotonRay;

ClDevice& device() {
    static ClDevice d;
    return d;
}
const cl::Program& program() {
    static cl::Program p = device().build({"photon_march.cl", "lattice.cl"});
    return p;
}

// A box grid of medium: occupancy 1 inside a one-voxel empty rim.
Voxelisation slabGrid(std::array<int, 3> dims, double voxel, const Rgb& sigmaT) {
    Voxelisation v;
    v.shape.dims = dims;
    v.shape.voxel = voxel;
    v.material.assign(v.shape.count(), glm::vec4(0.0f));
    v.refraction.assign(v.shape.count(), glm::vec4(1.0f, 0.0f, 0.0f, 0.0f));
    for (int z = 1; z < dims[2] - 1; ++z)
        for (int y = 1; y < dims[1] - 1; ++y)
            for (int x = 1; x < dims[0] - 1; ++x)
                v.material[x + dims[0] * (y + size_t(dims[1]) * z)] = glm::vec4(glm::vec3(sigmaT), 1.0f);
    return v;
}

PhotonRay rayAt(const Vec3& p, const Vec3& velocity) {
    PhotonRay r{};
    r.position = {{float(p.x), float(p.y), float(p.z), 1.0f}};
    r.velocity = {{float(velocity.x), float(velocity.y), float(velocity.z), 0.0f}};
    r.power = {{1.0f, 1.0f, 1.0f, 0.0f}};
    return r;
}

// Marches one ray until it leaves the grid; returns its last state.
PhotonRay marchOne(const Voxelisation& grid, const PhotonRay& start, double step) {
    RayMap map;
    map.rays = {start};
    map.emitted = Rgb(1.0);
    PhotonMarcher marcher(device(), program(), grid, Rgb(0.0), map, step);
    for (int i = 0; i < 100 && marcher.rays(device().marchQueue)[0].position.s[3] != 0.0f; ++i)
        marcher.enqueueMarch(device().marchQueue, 64, 0);
    return marcher.rays(device().marchQueue)[0];
}

// An index field n(y) on voxel centres, with its gradient by central differences (as voxelise makes it).
void setIndex(Voxelisation& grid, const std::vector<float>& nOfRow) {
    const auto& d = grid.shape.dims;
    grid.refracting = true;
    for (int z = 0; z < d[2]; ++z)
        for (int y = 0; y < d[1]; ++y)
            for (int x = 0; x < d[0]; ++x) {
                const int lo = std::max(y - 1, 0), hi = std::min(y + 1, d[1] - 1);
                grid.refraction[x + d[0] * (y + size_t(d[1]) * z)] =
                    glm::vec4(nOfRow[y], 0.0f, (nOfRow[hi] - nOfRow[lo]) / ((hi - lo) * grid.shape.voxel), 0.0f);
            }
}

TEST(Eikonal, FollowsTheAnalyticRayInALinearIndexGradient) {
    // n(y) = 1 + G y. With v = n dx/ds and dsigma = ds / n, the ray equation gives
    // d^2 n / dsigma^2 = G^2 n and dx/dsigma = v_x, so
    //   n(sigma) = n0 cosh(G sigma) + v_y0 sinh(G sigma),  x = x0 + v_x sigma.
    const int side = 96;
    Voxelisation grid = slabGrid({side, side, 8}, 1.0 / side, Rgb(0.0));
    const double G = 0.5;  // n from 1 to 1.5 over the unit box
    std::vector<float> n(side);
    for (int y = 0; y < side; ++y) n[y] = float(1.0 + G * (y + 0.5) / side);
    setIndex(grid, n);
    const Vec3 p0(0.01, 0.2, 0.05);
    const double n0 = 1.0 + G * p0.y;
    const Vec3 v0 = n0 * glm::normalize(Vec3(1.0, 0.4, 0.0));
    const PhotonRay end = marchOne(grid, rayAt(p0, v0), 0.25 / side);
    const double x = end.position.s[0], y = end.position.s[1];
    const double sigma = (x - p0.x) / v0.x;
    const double nExpected = n0 * std::cosh(G * sigma) + v0.y * std::sinh(G * sigma);
    const double yExpected = (nExpected - 1.0) / G;
    // Straight, the ray would end at p0.y + 0.4 (x - p0.x): far from both.
    EXPECT_GT(std::abs(yExpected - (p0.y + 0.4 * (x - p0.x))), 0.05);
    EXPECT_NEAR(y, yExpected, 2e-3) << "x " << x;
    // v_x is the Snell invariant: the gradient has no x component.
    EXPECT_NEAR(end.velocity.s[0], v0.x, 1e-5);
}

TEST(Eikonal, SnellAndFresnelAcrossSmoothedInterface) {
    // n = 1 below y = 0.5, 1.5 above, blurred over 0.75 voxel as voxelise does.
    // The ray bends by Snell's law and keeps Fresnel's transmission of its power,
    // here in the angle form (Born and Wolf, Principles of Optics, 1.5.3).
    const int side = 64;
    Voxelisation grid = slabGrid({side, side, 8}, 1.0 / side, Rgb(0.0));
    std::vector<float> field(grid.shape.count());
    const auto& d = grid.shape.dims;
    for (size_t i = 0; i < field.size(); ++i) field[i] = (i / d[0]) % d[1] >= size_t(side / 2) ? 1.5f : 1.0f;
    gaussianBlur(field, d, 0.75);
    std::vector<float> row(side);
    for (int y = 0; y < side; ++y) row[y] = field[side / 2 + d[0] * (y + size_t(d[1]) * 4)];
    setIndex(grid, row);
    grid.ior = 1.5;
    for (double degrees : {10.0, 30.0, 50.0, 60.0}) {
        const double t = degrees * kPi / 180.0, refracted = std::asin(std::sin(t) / 1.5);
        const PhotonRay end =
            marchOne(grid, rayAt(Vec3(0.05, 0.05, 0.05), Vec3(std::sin(t), std::cos(t), 0.0)), 0.5 / side);
        const double sinOut = end.velocity.s[0] / std::hypot(end.velocity.s[0], end.velocity.s[1]);
        EXPECT_NEAR(sinOut, std::sin(t) / 1.5, 0.01 * std::sin(t) / 1.5) << degrees << " degrees";
        const double rs = std::sin(t - refracted) / std::sin(t + refracted);
        const double rp = std::tan(t - refracted) / std::tan(t + refracted);
        EXPECT_NEAR(end.power.s[0], 1.0 - 0.5 * (rs * rs + rp * rp), 2e-3) << degrees << " degrees";
    }
}

TEST(PhotonMarching, DepositedPlusAbsorbedPlusEscapedIsEmitted) {
    test::ScratchDir dir;
    std::vector<std::string> warnings;
    const VolumeObject sphere(test::simpleObject(test::modelsDir() / "sphere.obj", 4.0, 0.7), warnings);
    const Voxelisation grid = voxelise(sphere, 24);
    Light light;
    light.type = Light::Type::Point;
    light.position = Vec3(3, 1, 2);
    light.power = Rgb(1.0, 2.0, 3.0);
    const RayMap map = rayMapFor({light}, grid.shape, 400, 7);
    PhotonMarcher marcher(device(), program(), grid, sphere.desc().medium.albedo, map, 0.5 * grid.shape.voxel);
    for (int i = 0; i < 40; ++i) marcher.enqueueMarch(device().marchQueue, 16, 0);
    for (const PhotonRay& r : marcher.rays(device().marchQueue)) ASSERT_EQ(r.position.s[3], 0.0f);
    const MarchTallies t = marcher.tallies(device().marchQueue);
    const Rgb deposited = marcher.deposited(device().marchQueue, 0);
    for (int c = 0; c < 3; ++c) {
        EXPECT_GT(deposited[c], 0.05 * map.emitted[c]);
        EXPECT_NEAR(deposited[c] + t.absorbed[c] + t.escaped[c], map.emitted[c], 1e-5 * map.emitted[c]);
        // albedo 0.7: scattered / absorbed = 0.7 / 0.3 along every ray
        EXPECT_NEAR(deposited[c] / t.absorbed[c], 0.7 / 0.3, 1e-3);
    }
}

// Injects power at one voxel of the lattice's source.
void inject(Lattice& lattice, size_t voxel, float power) {
    const glm::vec4 p(power, power, power, 0.0f);
    device().latticeQueue.enqueueWriteBuffer(lattice.source(), CL_TRUE, voxel * sizeof(glm::vec4), sizeof(p), &p);
}

TEST(Lattice, CollisionAndStreamingConservePower) {
    for (double albedo : {0.0, 0.5, 1.0}) {
        for (double opticalStep : {0.01, 0.5, 50.0}) {  // sigma_t lambda: far beyond what a linear kappa allows
            const int side = 16;
            const Voxelisation grid = slabGrid({side, side, side}, 1.0, Rgb(opticalStep));
            for (bool blocked : {false, true}) {
                Lattice lattice(device(), program(), grid, Rgb(albedo), blocked, 3);
                inject(lattice, 5 + side * (6 + side * 7), 1.0f);
                for (int i = 0; i < 7; ++i) lattice.enqueueLaunch(device().latticeQueue);
                const LatticeTotals t = lattice.totals(device().latticeQueue);
                const double total = t.absorbed.r + t.escaped.r + t.inFlight.r;
                EXPECT_NEAR(total, 1.0, 1e-5) << "albedo " << albedo << " sigma_t lambda " << opticalStep;
                for (const glm::vec4& v : lattice.fluenceTally(device().latticeQueue)) ASSERT_TRUE(std::isfinite(v.r));
                if (albedo == 1.0) {
                    EXPECT_EQ(t.absorbed.r, 0.0);
                }
            }
        }
    }
}

TEST(Lattice, PointSourceSpreadsAsThePersistentWalkOfItsCollisionMatrix) {
    // At albedo 1 a packet keeps its direction with chance (1 - k) + k / 6 and
    // takes each other one with k / 6 (k = 1 - exp(-sigma_t lambda)), so successive
    // unit steps correlate by r = 1 - k per axis and after n steps
    //   <R^2> = n + 2 sum_{m=1}^{n-1} (n - m) r^m   (lambda = 1),
    // whose slope gives the diffusion coefficient D = (1 + r) / (6 (1 - r)) = (2 / k - 1) / 6.
    const int side = 64;
    const double k = 0.3;
    const Voxelisation grid = slabGrid({side, side, side}, 1.0, Rgb(-std::log(1.0 - k)));
    auto expected = [&](int n) {
        double s = n;
        for (int m = 1; m < n; ++m) s += 2.0 * (n - m) * std::pow(1.0 - k, m);
        return s;
    };
    const int c = side / 2;
    Lattice lattice(device(), program(), grid, Rgb(1.0), false, 1);
    inject(lattice, c + side * (c + size_t(side) * c), 1.0f);
    // The mean squared distance of the mass that arrived at step n: the fluence
    // tally's increase over that step.
    auto spread = [&](std::vector<glm::vec4>& before) {
        lattice.enqueueLaunch(device().latticeQueue);
        const std::vector<glm::vec4> after = lattice.fluenceTally(device().latticeQueue);
        double mass = 0, moment = 0;
        for (size_t i = 0; i < after.size(); ++i) {
            const double m = after[i].r - before[i].r;
            const int x = int(i % side) - c, y = int((i / side) % side) - c, z = int(i / (side * side)) - c;
            mass += m;
            moment += m * (x * x + y * y + z * z);
        }
        before = after;
        return std::pair(mass, moment / mass);
    };
    std::vector<glm::vec4> tally(grid.shape.count(), glm::vec4(0.0f));
    lattice.enqueueLaunch(device().latticeQueue);  // the source is emitted: nothing has arrived yet
    tally = lattice.fluenceTally(device().latticeQueue);
    std::vector<double> msd(1, 0.0);
    for (int n = 1; n <= 30; ++n) {
        const auto [mass, r2] = spread(tally);
        EXPECT_NEAR(mass, 1.0, 1e-4) << n;  // albedo 1 and nowhere to escape yet
        EXPECT_NEAR(r2, expected(n), 1e-3 * expected(n)) << "step " << n;
        msd.push_back(r2);
    }
    const double slope = (msd[30] - msd[20]) / 10.0;
    EXPECT_NEAR(slope / 6.0, (2.0 / k - 1.0) / 6.0, 0.01 * (2.0 / k - 1.0) / 6.0);
}

TEST(Lattice, RefractingBoundaryReturnsItsShareAsAGeometricSeries) {
    // One voxel of medium alone in the air, at index 1.5: each step, what the
    // voxel sends out comes back reflected with share r and 1 - r leaves, so
    // of a source S, with q = 1 - (1 - a) k the share a collision keeps,
    //   escaped = (1 - r) S (1 + r q + (r q)^2 + ...) = (1 - r) S / (1 - r q).
    // r itself: the lattice's partial-current condition f- = r f+ puts the
    // extrapolated boundary at 3 D (1 + r) / (1 - r) where diffusion's puts it
    // at 2 D (1 + R) / (1 - R), R = 0.596325 at n = 1.5 (Walsh's closed form for
    // the diffuse reflectance from outside, 0.0917780, turned inside by
    // reciprocity, 1 - (1 - 0.0917780) / 1.5^2; tests/reference/refraction_test).
    const double R = 1.0 - (1.0 - 0.0917780) / 2.25;
    const double aLattice = 2.0 / 3.0 * (1.0 + R) / (1.0 - R), r = (aLattice - 1.0) / (aLattice + 1.0);
    EXPECT_NEAR(latticeBoundaryReflectance(1.5), r, 1e-6);
    EXPECT_EQ(latticeBoundaryReflectance(1.0), 0.0);
    const double k = 0.4, albedo = 0.8, q = 1.0 - (1.0 - albedo) * k;
    for (int at : {1, 4}) {  // inside a block, and on a block's face (its -x neighbour in the next block)
        Voxelisation grid = slabGrid({8, 8, 8}, 1.0, Rgb(0.0));
        grid.material.assign(grid.shape.count(), glm::vec4(0.0f));
        const size_t voxel = at + 8 * (at + 8 * size_t(at));
        grid.material[voxel] = glm::vec4(glm::vec3(float(-std::log(1.0 - k))), 1.0f);
        grid.ior = 1.5;
        for (bool blocked : {false, true}) {
            Lattice lattice(device(), program(), grid, Rgb(albedo), blocked, 3);
            inject(lattice, voxel, 1.0f);
            for (int i = 0; i < 60; ++i) lattice.enqueueLaunch(device().latticeQueue);
            const LatticeTotals t = lattice.totals(device().latticeQueue);
            EXPECT_NEAR(t.escaped.r, (1.0 - r) / (1.0 - r * q), 1e-5) << at << " blocked " << blocked;
            EXPECT_NEAR(t.escaped.r + t.absorbed.r + t.inFlight.r, 1.0, 1e-5) << at << " blocked " << blocked;
        }
    }
}

TEST(Lattice, BlockedMatchesGlobalLatticeOnceConverged) {
    std::vector<std::string> warnings;
    const VolumeObject sphere(test::simpleObject(test::modelsDir() / "sphere.obj", 6.0, 0.9), warnings);
    Voxelisation grid = voxelise(sphere, 20);
    for (double ior : {1.0, 1.5}) {  // the boundary reflects across blocks as within one
        grid.ior = ior;
        std::vector<std::vector<glm::vec4>> tallies;
        for (bool blocked : {false, true}) {
            Lattice lattice(device(), program(), grid, Rgb(0.9), blocked, 4);
            const auto& d = grid.shape.dims;
            inject(lattice, d[0] / 2 + d[0] * (d[1] / 3 + size_t(d[1]) * (d[2] / 2)), 1.0f);
            for (int i = 0; i < (blocked ? 150 : 600); ++i) lattice.enqueueLaunch(device().latticeQueue);
            EXPECT_LT(lattice.totals(device().latticeQueue).inFlight.r, 1e-6);
            tallies.push_back(lattice.fluenceTally(device().latticeQueue));
        }
        double largest = 0;
        for (const glm::vec4& v : tallies[0]) largest = std::max(largest, double(v.r));
        ASSERT_GT(largest, 0.0);
        for (size_t i = 0; i < tallies[0].size(); ++i)
            ASSERT_NEAR(tallies[1][i].r, tallies[0][i].r, 1e-4 * largest) << "voxel " << i << " ior " << ior;
    }
}

TEST(MultipleScattering, ProbesStopTheLatticeWithinItsTolerance) {
    // The probes extrapolate what is still to come; stopping at 1e-3 must leave the
    // grid within a few times that of a solve run to 1e-7.
    std::vector<std::string> warnings;
    const VolumeObject sphere(test::simpleObject(test::modelsDir() / "sphere.obj", 8.0, 0.95), warnings);
    const Light light = test::pointLight(Vec3(3, 3, 3), Rgb(40.0));
    MultipleScattering solver;
    HybridSettings s;
    s.resolution = 24;
    std::vector<double> totals;
    for (double tolerance : {1e-3, 1e-7}) {
        s.tolerance = tolerance;
        HybridStats stats;
        const ScatteringGrid g = solver.solve(sphere, {light}, s, &stats);
        EXPECT_TRUE(stats.converged);
        double total = 0;
        for (float v : g.source) total += v;
        totals.push_back(total);
        // Energy: what the rays brought is deposited, absorbed or escaped; what the
        // lattice received is absorbed, escaped or still in flight.
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(stats.injected[c] + stats.marchAbsorbed[c] + stats.marchEscaped[c], stats.emitted[c],
                        1e-4 * stats.emitted[c]);
            EXPECT_LT(stats.latticeInFlight[c], 10 * tolerance * stats.injected[c]);
        }
    }
    EXPECT_GT(totals[1], 0.0);
    EXPECT_NEAR(totals[0], totals[1], 5e-3 * totals[1]);
}

TEST(ClDevice, AKernelThatDoesNotBuildShowsItsLog) {
    try {
        device().buildSource("kernel void broken(global float* x) { x[0] = undeclared_name; }", "broken.cl");
        FAIL() << "built";
    } catch (const Error& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("broken.cl did not build"), std::string::npos) << what;
        EXPECT_NE(what.find("undeclared_name"), std::string::npos) << what;  // from the compiler's log
    }
}

TEST(ClDevice, AGridTooLargeForTheDeviceSaysHowMuchAndWhatToDo) {
    try {
        device().checkMemory(size_t(1) << 50, size_t(1) << 40, "a 9999^3 grid");
        FAIL() << "accepted";
    } catch (const Error& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("a 9999^3 grid"), std::string::npos) << what;
        EXPECT_NE(what.find("1073741824 MiB"), std::string::npos) << what;
        EXPECT_NE(what.find("smaller grid"), std::string::npos) << what;
    }
}

}  // namespace
}  // namespace lucent::hybrid
