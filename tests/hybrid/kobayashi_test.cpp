// Kobayashi's 3-D benchmark problems (models/transport/kobayashi-*.json,
// docs/transport.md) through `lucent transport`'s solver on the OpenCL device,
// at 10/3 cm cells (the files' 2 cm cells are the benchmark's,
// lucent-bench-hybrid kobayashi): every detector against the published fluxes
// of problem 1 (bench/kobayashi_reference.h) and, for the ducts of problems 2
// and 3, which have none here, against the uncollided flux integrated without
// cells (bench/uncollided_quadrature.h), itself checked against problem 1's
// exact values first. The bounds: 5% for the absorbers, 10% with
// scattering.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "bench/collided_monte_carlo.h"
#include "bench/kobayashi_reference.h"
#include "bench/uncollided_quadrature.h"
#include "core/transport_problem.h"
#include "hybrid/transport.h"

namespace lucent::hybrid {
namespace {

// The committed problem file with its cells replaced by `cells`.
TransportProblem problem(const std::string& name, const std::string& cells) {
    const std::string file = std::string(LUCENT_SOURCE_DIR) + "/models/transport/" + name;
    std::ifstream in(file);
    std::stringstream text;
    text << in.rdbuf();
    std::string s = text.str();
    const size_t at = s.find("\"cells\": [");
    EXPECT_NE(at, std::string::npos) << file;
    const size_t end = s.find(']', at);
    s.replace(at, end + 1 - at, "\"cells\": " + cells);
    return parseTransportProblemText(s, file);
}

const std::string kProblemOneCells = "[30, 30, 30]", kDuctCells = "[18, 30, 18]";  // 10/3 cm

TEST(Kobayashi, QuadratureReproducesProblemOnesExactFluxes) {
    // The truth of the ducts' tests, on the problem whose exact uncollided
    // fluxes are published: within 0.5%, a tenth of the bound it judges.
    const TransportProblem p = problem("kobayashi-1-absorber.json", kProblemOneCells);
    for (const KobayashiDetector& d : kKobayashiProblem1)
        EXPECT_NEAR(uncollidedQuadrature(p, d.at, 128), d.absorber, 0.005 * d.absorber)
            << d.set << " (" << d.at.x << ", " << d.at.y << ", " << d.at.z << ")";
}

TEST(Kobayashi, MonteCarloReproducesProblemOnesScatteringFluxes) {
    // The truth of the ducts' scattering cases (bench/collided_monte_carlo.h),
    // with the quadrature's uncollided flux, on the problem whose scattering
    // fluxes are published (their own error at most 0.6%): within 2% wherever
    // its standard error is under 1%. A second of histories reaches that at
    // the void's detectors and a few in the shield.
    const TransportProblem p = problem("kobayashi-1-scatter.json", kProblemOneCells);
    const CollidedEstimate c = collidedMonteCarlo(p, p.points, 20000);
    int tight = 0;
    for (size_t i = 0; i < std::size(kKobayashiProblem1); ++i) {
        const KobayashiDetector& d = kKobayashiProblem1[i];
        const double total = uncollidedQuadrature(p, d.at, 128) + c.flux[i];
        if (!(c.standardError[i] < 0.01 * total)) continue;
        ++tight;
        EXPECT_NEAR(total, d.scatter, 0.02 * d.scatter) << d.set << " (" << d.at.x << ", " << d.at.y << ", " << d.at.z
                                                        << "), standard error " << c.standardError[i] / total;
    }
    EXPECT_GE(tight, 15);
}

// Problem 1's case `file` solved, every detector within `bound` of its truth.
TransportResult expectProblemOne(const std::string& file, double KobayashiDetector::*truth, double bound,
                                 int directions = 0) {
    TransportProblem p = problem(file, kProblemOneCells);
    if (directions > 0) p.directions = directions;
    EXPECT_EQ(p.points.size(), std::size(kKobayashiProblem1));
    const TransportResult r = solveTransport(p);
    for (size_t i = 0; i < std::min(p.points.size(), std::size(kKobayashiProblem1)); ++i) {
        const KobayashiDetector& d = kKobayashiProblem1[i];
        EXPECT_EQ(p.points[i], d.at);
        EXPECT_NEAR(r.flux[i], d.*truth, bound * d.*truth)
            << file << " " << d.set << " (" << d.at.x << ", " << d.at.y << ", " << d.at.z << ")";
    }
    return r;
}

TEST(Kobayashi, ProblemOneAbsorberMeetsEveryDetector) {
    // Reflective x-, y- and z- faces: the first-collision source needs the
    // source's 7 mirror images; without them the far diagonal was off by
    // orders of magnitude (5.8e-12 against 3.0e-6).
    EXPECT_TRUE(expectProblemOne("kobayashi-1-absorber.json", &KobayashiDetector::absorber, 0.05).uncollidedMarched);
}

TEST(Kobayashi, ProblemOneWithScatteringMeetsEveryDetector) {
    // Half of every collision scatters, against the report's Monte Carlo
    // values (their own error is at most 0.6%). At 48 directions the light
    // scattered in the source and swept across the void missed the far
    // detectors by up to 21% (ray effects); the first-collided source takes
    // it out of the sweeps (docs/transport.md).
    EXPECT_TRUE(expectProblemOne("kobayashi-1-scatter.json", &KobayashiDetector::scatter, 0.10, 48).converged);
}

TEST(Kobayashi, DuctProblemsMeetTheirUncollidedFluxAtEveryDetector) {
    // The straight duct (problem 2) and the dog-leg (problem 3): along the
    // void and into the shield beside it.
    for (const char* name : {"kobayashi-2-absorber.json", "kobayashi-3-absorber.json"}) {
        const TransportProblem p = problem(name, kDuctCells);
        const TransportResult r = solveTransport(p);
        EXPECT_TRUE(r.uncollidedMarched) << name;
        for (size_t i = 0; i < p.points.size(); ++i) {
            const Vec3& x = p.points[i];
            const double truth = uncollidedQuadrature(p, x, 128);
            EXPECT_NEAR(r.flux[i], truth, 0.05 * truth) << name << " (" << x.x << ", " << x.y << ", " << x.z << ")";
        }
    }
}

}  // namespace
}  // namespace lucent::hybrid
