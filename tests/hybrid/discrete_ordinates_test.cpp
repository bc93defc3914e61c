// The discrete ordinates solver (thesis 5.3) on the OpenCL device, against
// independent truths: the angular quadratures and delta-M phase function
// against their defining integrals; an infinite medium with a uniform source
// (flux q / sigma_a exactly); a pure absorber against the uncollided flux
// integrated independently; and the van de Hulst slab (HG g = 0.75).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include <glm/gtc/matrix_transform.hpp>

#include "core/error.h"
#include "core/spherical_harmonics.h"
#include "hybrid/internal/cl_device.h"
#include "hybrid/internal/dom_solver.h"
#include "hybrid/ordinates.h"
#include "hybrid/transport.h"

namespace lucent::hybrid {
namespace {

ClDevice& device() {
    static ClDevice d;
    return d;
}

// A slab of optical thickness b between z = 0 and z = b (sigma_t = 1), infinite
// across (one wide cell per axis, reflecting sides), lit at normal incidence
// by a unit flux; returns {Rd, Tt}: what leaves through z = 0 and z = b per
// unit incident flux, direct transmission included.
std::pair<double, double> slab(double albedo, double g, double b, int cells, int directions, int bands) {
    DomGrid grid;
    grid.dims = {1, 1, cells};
    const double dz = b / cells;
    grid.edges = Vec3(1e3, 1e3, dz);
    const DeltaM dm = deltaM(g, bands);
    const double sigmaT = 1.0 - dm.f * albedo, sigmaS = (1.0 - dm.f) * albedo;
    grid.extinction.assign(cells, glm::vec4(glm::vec3(float(sigmaT)), 1.0f));
    grid.scattering.assign(cells, glm::vec4(glm::vec3(float(sigmaS)), 0.0f));
    grid.phase.assign(cells, glm::vec4(float(g), 0.0f, 0.0f, 0.0f));
    DomSolver solver(device(), grid, directions, bands, {true, true, true, true, false, false});
    const int m = bands * bands;
    std::vector<double> y(m);
    evaluateSh(bands, Vec3(0, 0, 1), y);
    std::vector<glm::vec4> source(size_t(cells) * m, glm::vec4(0.0f));
    for (int k = 0; k < cells; ++k) {
        // The scaled beam's average over the cell, exp(-sigma* z) integrated exactly.
        const double e = (std::exp(-sigmaT * k * dz) - std::exp(-sigmaT * (k + 1) * dz)) / (sigmaT * dz);
        for (int i = 0; i < m; ++i) {
            const int l = int(std::sqrt(double(i)));
            source[size_t(k) * m + i] = glm::vec4(glm::vec3(float(sigmaS * dm.moments[l] * e * y[i])), 0.0f);
        }
    }
    cl::CommandQueue& q = device().marchQueue;
    solver.setSource(q, source);
    const Ordinates& o = solver.ordinates();
    const std::array<int, 3> dims = grid.dims;
    double rd = 0.0, td = 0.0, last = 0.0, previous = 0.0;
    for (int it = 0; it < 400; ++it) {
        const double power = solver.iterate(q).r;
        const std::vector<glm::vec4> out = solver.boundaryRadiance(q);
        double r = 0.0, t = 0.0;
        for (size_t n = 0; n < o.directions.size(); ++n) {
            const double mu = o.directions[n].z;
            if (mu < 0.0) r += o.weights[n] * -mu * out[DomSolver::faceOffset(4, dims, int(o.directions.size())) + n].r;
            if (mu > 0.0) t += o.weights[n] * mu * out[DomSolver::faceOffset(5, dims, int(o.directions.size())) + n].r;
        }
        rd += r;
        td += t;
        previous = last;
        last = power;
        if (it > 3 && power < 1e-7 * (rd + td)) break;
    }
    (void)previous;
    return {rd, td + std::exp(-sigmaT * b)};  // the scaled beam carries the forward peak through
}

TEST(DiscreteOrdinates, QuadraturesIntegrateTheHarmonicsTheSolverUses) {
    // int Y_lm = sqrt(4 pi) for l = 0 and 0 otherwise; int w w^T = 4 pi / 3 I.
    // The first makes scattering conserve energy, the second keeps the flux's
    // direction: both closed forms, checked up to the most bands stored (6).
    for (int count : ordinateCounts()) {
        const Ordinates o = ordinatesFor(count);
        ASSERT_EQ(int(o.directions.size()), count);
        std::vector<double> sum(36, 0.0), y(36);
        glm::dmat3 second(0.0);
        for (size_t n = 0; n < o.directions.size(); ++n) {
            EXPECT_NEAR(glm::length(o.directions[n]), 1.0, 1e-12);
            evaluateSh(6, o.directions[n], y);
            for (int i = 0; i < 36; ++i) sum[i] += o.weights[n] * y[i];
            second += o.weights[n] * glm::outerProduct(o.directions[n], o.directions[n]);
        }
        EXPECT_NEAR(sum[0], std::sqrt(4.0 * kPi), 1e-9) << count;
        // The level-symmetric tables carry 7 digits: l = 4 vanishes to about 1e-7 there.
        for (int i = 1; i < 36; ++i) EXPECT_NEAR(sum[i], 0.0, 1e-6) << count << " moment " << i;
        for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b) EXPECT_NEAR(second[a][b], a == b ? 4.0 * kPi / 3.0 : 0.0, 2e-6) << count;
    }
}

TEST(DiscreteOrdinates, DiscretePhaseFunctionConservesEnergyAndMeanCosine) {
    // The delta-M phase function on the quadrature, p(w_n, w') = f delta +
    // (1 - f) sum_l g*_l sum_m Y_lm(w_n) Y_lm(w'), must integrate to 1 (energy)
    // and keep Henyey-Greenstein's mean cosine g, for any incident w' and g in
    // [-0.95, 0.95] (the mean cosine up to 4 bands: 6 take more than 24 directions resolve).
    const Vec3 incident[] = {glm::normalize(Vec3(0.3, -0.5, 0.8)), Vec3(0, 0, 1), glm::normalize(Vec3(-1, 2, 0.1))};
    for (int count : {24, 120})
        for (int bands : {2, 3, 4, 6}) {
            const Ordinates o = ordinatesFor(count);
            const int m = bands * bands;
            std::vector<double> yn(m), yi(m);
            for (double g = -0.95; g <= 0.951; g += 0.1) {
                const DeltaM dm = deltaM(g, bands);
                for (const Vec3& wi : incident) {
                    evaluateSh(bands, wi, yi);
                    double total = 0.0, meanCos = 0.0;
                    for (size_t n = 0; n < o.directions.size(); ++n) {
                        evaluateSh(bands, o.directions[n], yn);
                        double p = 0.0;
                        for (int i = 0; i < m; ++i) p += dm.moments[int(std::sqrt(double(i)))] * yn[i] * yi[i];
                        total += o.weights[n] * (1.0 - dm.f) * p;
                        meanCos += o.weights[n] * (1.0 - dm.f) * p * glm::dot(o.directions[n], wi);
                    }
                    EXPECT_NEAR(dm.f + total, 1.0, 1e-6) << count << " g " << g;
                    if (bands >= 2 && bands <= 4) {
                        EXPECT_NEAR(dm.f + meanCos, g, 1e-5) << count << " g " << g;
                    }
                }
            }
        }
}

TEST(DiscreteOrdinates, VoxelCrossingTubesCarryTheFluxThroughTheFaces) {
    // Every point of an Out face is reached from exactly one In face, and the
    // light entering face a (flux A_a w_a per unit radiance) leaves through the
    // Out faces: sum_Out tube[a][Out] = A_a w_a / V = w_a / h_a.
    const Vec3 edges(1.0, 0.5, 2.0);
    for (const Vec3& d :
         {glm::normalize(Vec3(0.3, 0.5, 0.8)), glm::normalize(Vec3(1, 1, 1)), glm::normalize(Vec3(0.9, 0.05, 0.1))}) {
        const VoxelCrossing c = voxelCrossing(d, edges);
        for (int b = 0; b < 3; ++b) EXPECT_NEAR(c.share[0][b] + c.share[1][b] + c.share[2][b], 1.0, 1e-9);
        for (int a = 0; a < 3; ++a)
            EXPECT_NEAR(c.tube[a][0] + c.tube[a][1] + c.tube[a][2], d[a] / edges[a], 1e-9 * d[a] / edges[a]);
        // A straight path from face x through the voxel to the opposite face is h_x / w_x long.
        if (c.share[0][0] > 0.0) {
            EXPECT_NEAR(c.length[0][0], edges.x / d.x, 0.01 * edges.x / d.x);
        }
    }
}

TEST(DiscreteOrdinates, VanDeHulstSlab) {
    // van de Hulst (1980), Multiple Light Scattering vol. 2, table 35: HG
    // g = 0.75, albedo 0.9, optical thickness 2, normal incidence,
    // index-matched: Rd = 0.09739, Tt = 0.66096. The bound follows the angular
    // resolution: 16 moments hold the scaled phase function to l = 3 and 120
    // directions resolve the exit distributions to about 1%; 24 directions
    // leave about a 3% error on the reflected light, whose distribution is the
    // least smooth (measured 0.5% and 2.7%).
    const double rdRef = 0.09739, ttRef = 0.66096;
    for (const auto& [n, bound] : {std::pair{24, 0.03}, std::pair{120, 0.01}}) {
        const auto [rd, tt] = slab(0.9, 0.75, 2.0, 200, n, 4);
        EXPECT_NEAR(rd, rdRef, bound * rdRef) << n << " directions";
        EXPECT_NEAR(tt, ttRef, 0.01 * ttRef) << n << " directions";
    }
}

// The uncollided scalar flux at x of an isotropic source q filling box in a
// medium of extinction sigma everywhere: q / (4 pi) int dOmega int e^{-sigma r} dr
// over the part of each ray from x inside the box, by a product rule in
// (cos theta, phi) fine enough for the box's solid angle.
TEST(DiscreteOrdinates, RefractingSlabReflectsItsOwnLightInside) {
    // A purely absorbing slab of index 1.5 and optical thickness tau, infinite
    // across, glowing with a uniform isotropic source q, between layers of air.
    // Along a direction at cosine mu to the normal a crossing adds
    // A = q / sigma (1 - t), t = e^{-tau / mu}, and each boundary sends back R(mu)
    // (Fresnel, Born and Wolf's angle form): the radiance leaving the top is
    //   (1 - R) (A + R t A + (R t)^2 A + ...) = (1 - R) A / (1 - R t),
    // 0 past the critical angle. The index-matched slab gives A.
    const int cells = 10;
    const double dz = 0.25, sigma = 1.0, q = 0.7, tau = sigma * dz * (cells - 2);
    for (double ior : {1.0, 1.5}) {
        DomGrid grid;
        grid.dims = {1, 1, cells};
        grid.edges = Vec3(1e3, 1e3, dz);
        grid.extinction.assign(cells, glm::vec4(glm::vec3(float(sigma)), 1.0f));
        grid.extinction.front() = grid.extinction.back() = glm::vec4(0.0f);  // air
        grid.scattering.assign(cells, glm::vec4(0.0f));
        grid.phase.assign(cells, glm::vec4(0.0f));
        grid.ior = ior;
        for (int k = 0; k < cells; ++k) grid.boundaryNormal.push_back(glm::vec3(0, 0, k < cells / 2 ? -1 : 1));
        DomSolver solver(device(), grid, 48, 1, {true, true, true, true, false, false});
        const float y00 = float(0.5 / std::sqrt(kPi));  // the source towards any direction is s_0 Y_00
        std::vector<glm::vec4> source(cells, glm::vec4(glm::vec3(float(q) / y00), 0.0f));
        source.front() = source.back() = glm::vec4(0.0f);
        cl::CommandQueue& queue = device().marchQueue;
        solver.setSource(queue, source);
        const Ordinates& o = solver.ordinates();
        const int n = int(o.directions.size());
        const size_t top = DomSolver::faceOffset(5, grid.dims, n);
        std::vector<double> leaving(n, 0.0);
        for (int it = 0; it < 40; ++it) {  // one reflection per iteration; (R t)^40 is far below 1e-6
            solver.iterate(queue);
            const std::vector<glm::vec4> out = solver.boundaryRadiance(queue);
            for (int i = 0; i < n; ++i) leaving[i] += out[top + i].r;
        }
        for (int i = 0; i < n; ++i) {
            const double mu = o.directions[i].z;
            if (mu <= 0.0) continue;
            const double t = std::exp(-tau / mu), a = q / sigma * (1.0 - t);
            double expected = a;
            if (ior != 1.0) {
                const double sinT = std::sqrt(1.0 - mu * mu) * ior;  // outside
                double r = 1.0;
                if (sinT < 1.0) {
                    const double inside = std::acos(mu), outside = std::asin(sinT);
                    const double rs = std::sin(inside - outside) / std::sin(inside + outside);
                    const double rp = std::tan(inside - outside) / std::tan(inside + outside);
                    r = 0.5 * (rs * rs + rp * rp);
                }
                expected = (1.0 - r) * a / (1.0 - r * t);
            }
            EXPECT_NEAR(leaving[i], expected, 1e-3 * q / sigma) << "ior " << ior << " mu " << mu;
        }
    }
}

double uncollidedFlux(const Vec3& x, const Bounds3& box, double q, double sigma) {
    constexpr int kMu = 2000, kPhi = 4000;
    double sum = 0.0;
    for (int i = 0; i < kMu; ++i) {
        const double mu = -1.0 + (i + 0.5) * 2.0 / kMu, s = std::sqrt(1.0 - mu * mu);
        for (int j = 0; j < kPhi; ++j) {
            const double phi = (j + 0.5) * 2.0 * kPi / kPhi;
            const Vec3 d(s * std::cos(phi), s * std::sin(phi), mu);
            double t0 = 0.0, t1 = kInfinity;
            if (clipToBox(box, x, d, t0, t1))
                sum += sigma > 0.0 ? (std::exp(-sigma * t0) - std::exp(-sigma * t1)) / sigma : t1 - t0;
        }
    }
    return q / (4.0 * kPi) * sum * (2.0 / kMu) * (2.0 * kPi / kPhi);
}

TEST(Transport, InfiniteMediumWithUniformSourceGivesSourceOverAbsorption) {
    // Reflecting faces make the box an infinite medium: every particle emitted
    // is absorbed somewhere, and by symmetry everywhere alike, so the scalar
    // flux is q / sigma_a exactly, whatever the scattering and its phase function.
    for (double g : {0.0, 0.6}) {
        const std::string text = R"({"domain": {"min": [0, 0, 0], "max": [2, 3, 4], "cells": [4, 6, 8]},
            "boundary": {"x-": "reflective", "x+": "reflective", "y-": "reflective", "y+": "reflective",
                         "z-": "reflective", "z+": "reflective"},
            "regions": [{"min": [0, 0, 0], "max": [2, 3, 4], "sigma_t": 2.0, "sigma_s": 1.5, "g": )" +
                                 std::to_string(g) + R"(, "source": 3.0}],
            "points": [[0.1, 0.1, 0.1], [1, 1.5, 2], [1.9, 2.9, 3.9]],
            "solver": {"directions": 24, "bands": 4, "tolerance": 1e-6}})";
        const TransportResult r = solveTransport(parseTransportProblemText(text, "infinite.json"));
        EXPECT_TRUE(r.converged);
        for (double flux : r.flux) EXPECT_NEAR(flux, 3.0 / 0.5, 1e-3 * 6.0) << "g " << g;
    }
}

// A problem larger than the machine: refused with what it needs, before any
// allocation (2^24 cells at 36 moments and 168 directions ask for well over
// this machine's 23 GB; a 256^3 mdom grid that once passed the device's own
// figure was killed by the kernel at 24 GB instead).
TEST(Transport, AProblemLargerThanTheMachineIsRefusedWithWhatItNeeds) {
    const std::string text = R"({"domain": {"min": [0, 0, 0], "max": [1, 1, 1], "cells": [1024, 1024, 16]},
        "regions": [{"min": [0, 0, 0], "max": [1, 1, 1], "sigma_t": 1.0, "sigma_s": 0.5, "source": 1.0}],
        "points": [[0.5, 0.5, 0.5]], "solver": {"directions": 168, "bands": 6}})";
    try {
        solveTransport(parseTransportProblemText(text, "huge.json"));
        FAIL() << "no error";
    } catch (const Error& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("cannot hold the 1024x1024x16 cells of huge.json: it needs"), std::string::npos)
            << message;
        EXPECT_NE(message.find("use a smaller grid"), std::string::npos) << message;
    }
}

// A unit cube source at the centre of a 5^3 box of 0.2 cells, vacuum all
// round, in a pure absorber of extinction sigma; the flux at `points`.
TransportResult cubeSource(double sigma, const std::string& points, const std::string& solver) {
    const std::string s = std::to_string(sigma);
    const std::string text = R"({"domain": {"min": [0, 0, 0], "max": [5, 5, 5], "cells": [25, 25, 25]},
        "regions": [{"min": [0, 0, 0], "max": [5, 5, 5], "sigma_t": )" +
                             s + R"(},
                    {"min": [2, 2, 2], "max": [3, 3, 3], "sigma_t": )" +
                             s + R"(, "source": 1.0}],
        "points": )" + points +
                             R"(, "solver": )" + solver + "}";
    return solveTransport(parseTransportProblemText(text, "absorber.json"));
}

TEST(Transport, SweptSourceInAPureAbsorberGivesTheUncollidedFlux) {
    // The sweeps carrying the source themselves, as they must with reflective
    // faces: inside the source every direction set does well; one source width
    // away the discrete directions miss the source's solid angle unevenly (ray
    // effects), which 120 directions keep within the renderer's 10% goal.
    const std::vector<Vec3> points{Vec3(2.5, 2.5, 2.5), Vec3(2.5, 2.5, 3.9), Vec3(3.9, 3.9, 3.9)};
    const TransportResult r = cubeSource(1.0, "[[2.5, 2.5, 2.5], [2.5, 2.5, 3.9], [3.9, 3.9, 3.9]]",
                                         R"({"directions": 120, "bands": 4, "uncollided": "swept"})");
    EXPECT_FALSE(r.uncollidedMarched);
    // Inside the source the step scheme's cell average is within 5% of the
    // point value (measured 3.9%); outside, within the 10% goal of the
    // renderer's methods (measured 5.5% and 1.9% at 120 directions).
    const double bounds[] = {0.05, 0.10, 0.10};
    for (size_t i = 0; i < points.size(); ++i) {
        const double truth = uncollidedFlux(points[i], Bounds3{Vec3(2.0), Vec3(3.0)}, 1.0, 1.0);
        EXPECT_NEAR(r.flux[i], truth, bounds[i] * truth) << "point " << i;
    }
}

// The bound of the marched uncollided flux: the near kernels are integrated to
// about 0.1%; the point kernel of the far cells is off their average by about
// 1 / (6 D^2), under 1% from D = 4 cells; a cell's average is off the value at
// its centre by h^2 / 24 times the flux's relative Laplacian, under 1% here
// (the flux varies on the source's scale, five cells). 2% holds all three.
constexpr double kMarchedBound = 0.02;

TEST(Transport, MarchedUncollidedFluxHasNoRayEffects) {
    // The problem above at 24 directions, where sweeping it misses the far
    // diagonal by 93% (docs/transport.md): the first-collision source leaves
    // no uncollided light to the directions.
    const std::vector<Vec3> points{Vec3(2.5, 2.5, 2.5), Vec3(2.5, 2.5, 3.9), Vec3(3.9, 3.9, 3.9), Vec3(2.5, 2.5, 4.7),
                                   Vec3(4.7, 4.7, 4.7)};
    const TransportResult r =
        cubeSource(1.0, "[[2.5, 2.5, 2.5], [2.5, 2.5, 3.9], [3.9, 3.9, 3.9], [2.5, 2.5, 4.7], [4.7, 4.7, 4.7]]",
                   R"({"directions": 24, "bands": 4})");
    EXPECT_TRUE(r.uncollidedMarched);  // auto marches with vacuum all round
    EXPECT_TRUE(r.uncollidedWhy.empty());
    for (size_t i = 0; i < points.size(); ++i) {
        const double truth = uncollidedFlux(points[i], Bounds3{Vec3(2.0), Vec3(3.0)}, 1.0, 1.0);
        EXPECT_NEAR(r.flux[i], truth, kMarchedBound * truth) << "point " << i;
    }
}

TEST(Transport, MarchedUncollidedFluxHoldsInVacuumAndInOpaqueMedia) {
    // No extinction at all: the flux is the source's chord integral.
    const std::vector<Vec3> points{Vec3(2.5, 2.5, 2.5), Vec3(2.5, 2.5, 3.9), Vec3(4.7, 4.7, 4.7)};
    const TransportResult vacuum = cubeSource(0.0, "[[2.5, 2.5, 2.5], [2.5, 2.5, 3.9], [4.7, 4.7, 4.7]]",
                                              R"({"directions": 24, "bands": 4, "uncollided": "marched"})");
    for (size_t i = 0; i < points.size(); ++i) {
        const double truth = uncollidedFlux(points[i], Bounds3{Vec3(2.0), Vec3(3.0)}, 1.0, 0.0);
        EXPECT_NEAR(vacuum.flux[i], truth, kMarchedBound * truth) << "point " << i;
    }
    // Ten mean free paths per cell: at the source's centre every particle is
    // absorbed within a cell, flux q / sigma_t up to e^{-25}.
    const TransportResult opaque = cubeSource(50.0, "[[2.5, 2.5, 2.5]]", R"({"directions": 24, "bands": 4})");
    EXPECT_NEAR(opaque.flux[0], 1.0 / 50.0, 1e-3 / 50.0);
    for (float f : opaque.cellFlux) EXPECT_TRUE(std::isfinite(f) && f >= 0.0f);
}

TEST(Transport, FirstCollisionSourceScattersToTheInfiniteMediumFlux) {
    // A uniform source filling a box 10 diffusion lengths across its half
    // (sigma_t 2, sigma_s 1; L = 1 / sqrt(3 sigma_a sigma_tr) <= 0.41), vacuum
    // outside: at the centre the flux is the infinite medium's q / sigma_a up
    // to a leakage of order e^{-12}. The marched uncollided flux and the swept
    // collided light must add up to it, whatever the phase function. Bound
    // 0.5%: the step scheme is exact in a uniform medium, the near kernels
    // hold the uncollided half to 0.1% (measured 0.06% and 0.15%).
    for (double g : {0.0, 0.6}) {
        const std::string text = R"({"domain": {"min": [0, 0, 0], "max": [10, 10, 10], "cells": [13, 13, 13]},
            "regions": [{"min": [0, 0, 0], "max": [10, 10, 10], "sigma_t": 2.0, "sigma_s": 1.0, "g": )" +
                                 std::to_string(g) + R"(, "source": 1.0}],
            "points": [[5, 5, 5]], "solver": {"directions": 24, "bands": 4, "tolerance": 1e-6}})";
        const TransportResult r = solveTransport(parseTransportProblemText(text, "box.json"));
        EXPECT_TRUE(r.uncollidedMarched);
        EXPECT_TRUE(r.converged);
        EXPECT_NEAR(r.flux[0], 1.0, 0.005) << "g " << g;
    }
}

TEST(Transport, MarchingIsRefusedWhereItCannotHold) {
    // Both faces of an axis reflecting would mirror the sources' images
    // without end: auto sweeps and says why; asked for, marching is refused
    // with the reason. One reflective face per axis marches.
    const std::string text = R"({"domain": {"min": [0, 0, 0], "max": [1, 1, 1], "cells": [4, 4, 4]},
        "boundary": {"z-": "reflective", "z+": "FACE"},
        "regions": [{"min": [0, 0, 0], "max": [1, 1, 1], "sigma_t": 1.0, "source": 1.0}],
        "points": [[0.5, 0.5, 0.5]], "solver": {"directions": 24, "uncollided": "HOW"}})";
    auto with = [&](const std::string& face, const std::string& how) {
        std::string t = text;
        t.replace(t.find("FACE"), 4, face);
        t.replace(t.find("HOW"), 3, how);
        return parseTransportProblemText(t, "mirror.json");
    };
    const TransportResult r = solveTransport(with("reflective", "auto"));
    EXPECT_FALSE(r.uncollidedMarched);
    EXPECT_NE(r.uncollidedWhy.find("both z faces are reflective"), std::string::npos) << r.uncollidedWhy;
    try {
        solveTransport(with("reflective", "marched"));
        FAIL() << "no error";
    } catch (const Error& e) {
        const std::string message = e.what();
        EXPECT_EQ(
            message.rfind("mirror.json: /solver/uncollided: cannot be \"marched\": both z faces are reflective", 0), 0u)
            << message;
    }
    EXPECT_TRUE(solveTransport(with("vacuum", "auto")).uncollidedMarched);
    // More source cells, their images counted, than the list and tree over
    // them are sized for: refused before they are built.
    const std::string many = R"({"domain": {"min": [0, 0, 0], "max": [1, 1, 1], "cells": [65, 65, 65]},
        "boundary": {"x-": "reflective", "y-": "reflective", "z-": "reflective"},
        "regions": [{"min": [0, 0, 0], "max": [1, 1, 1], "sigma_t": 1.0, "source": 1.0}],
        "points": [[0.5, 0.5, 0.5]], "solver": {"directions": 24, "bands": 1, "uncollided": "marched"}})";
    try {
        solveTransport(parseTransportProblemText(many, "many.json"));
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("274625 source cells and their mirror images, 2197000 in all, are more "
                                             "than the 2097152 it is integrated for"),
                  std::string::npos)
            << e.what();
    }
}

}  // namespace
}  // namespace lucent::hybrid
