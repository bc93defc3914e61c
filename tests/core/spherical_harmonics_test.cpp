#include "core/spherical_harmonics.h"

#include <gtest/gtest.h>

#include "core/sphere_directions.h"
#include "tests/support/test_support.h"

namespace lucent {
namespace {

// Closed forms for l <= 2, written from the definition
// Y_lm = sqrt(2) K_lm P_l^|m|(cos th) {cos, sin}(|m| ph) with the Condon-Shortley phase.
std::vector<double> closedFormsUpToL2(const Vec3& d) {
    const double x = d.x, y = d.y, z = d.z, pi = kPi;
    return {0.5 * std::sqrt(1 / pi),
            -std::sqrt(3 / (4 * pi)) * y,
            std::sqrt(3 / (4 * pi)) * z,
            -std::sqrt(3 / (4 * pi)) * x,
            0.5 * std::sqrt(15 / pi) * x * y,
            -0.5 * std::sqrt(15 / pi) * y * z,
            0.25 * std::sqrt(5 / pi) * (3 * z * z - 1),
            -0.5 * std::sqrt(15 / pi) * x * z,
            0.25 * std::sqrt(15 / pi) * (x * x - y * y)};
}

TEST(SphericalHarmonics, MatchesClosedFormsUpToBand2) {
    Rng rng(7, 0);
    std::vector<double> basis(9);
    for (int i = 0; i < 200; ++i) {
        const Vec3 d = randomRotation(rng) * Vec3(0, 0, 1);
        evaluateSh(3, d, basis);
        const auto expected = closedFormsUpToL2(d);
        for (int k = 0; k < 9; ++k) EXPECT_NEAR(basis[k], expected[k], 1e-12) << "index " << k;
    }
}

TEST(SphericalHarmonics, MatchesPublishedValuesUpToBand4) {
    // tests/data/real_sh_l4.csv, 'eval' rows: google/spherical-harmonics, sh/spherical_harmonics.cc.
    const auto rows = test::readCsv(test::dataDir() / "real_sh_l4.csv");
    std::vector<double> basis(25);
    int checked = 0;
    for (const auto& row : rows) {
        if (row[0] != "eval") continue;
        const std::string where = row[4];
        Vec3 d;
        if (where == "px")
            d = {1, 0, 0};
        else if (where == "py")
            d = {0, 1, 0};
        else if (where == "pz")
            d = {0, 0, 1};
        else if (where.rfind("diag(1", 0) == 0)
            d = glm::normalize(Vec3(1, 1, 1));
        else if (where == "phi=pi/4")
            d = {std::sin(kPi / 3) * std::cos(kPi / 4), std::sin(kPi / 3) * std::sin(kPi / 4), std::cos(kPi / 3)};
        else if (where == "google_test_phi0.4296_theta1.73234")
            d = {std::sin(1.73234) * std::cos(0.4296), std::sin(1.73234) * std::sin(0.4296), std::cos(1.73234)};
        else
            FAIL() << "unknown direction " << where;
        const int index = std::stoi(row[3]);
        evaluateSh(5, d, basis);
        EXPECT_NEAR(basis[index], std::stod(row.back()), 2e-6) << where << " index " << index;
        ++checked;
    }
    EXPECT_GT(checked, 100);
}

TEST(SphericalHarmonics, OrthonormalUnderQuadrature) {
    const int order = 8, n = order * order;
    const auto dirs = fibonacciSphere(20000);
    std::vector<double> gram(n * n, 0.0), basis(n);
    for (const Vec3& d : dirs) {
        evaluateSh(order, d, basis);
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j) gram[i * n + j] += basis[i] * basis[j] * 4 * kPi / dirs.size();
    }
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) EXPECT_NEAR(gram[i * n + j], i == j ? 1.0 : 0.0, 2e-3) << i << "," << j;
}

TEST(SphericalHarmonics, ClampedCosineProjectionMatchesPublishedZonalCoefficients) {
    // tests/data/sh_projections_clamped_cosine_delta.csv (pbrt-v2, exact values).
    const int order = 9;
    std::vector<double> coefficients(order * order, 0.0), basis(order * order);
    const auto dirs = fibonacciSphere(200000);
    for (const Vec3& d : dirs) {
        evaluateSh(order, d, basis);
        const double f = std::max(d.z, 0.0);
        for (int k = 0; k < order * order; ++k) coefficients[k] += f * basis[k] * 4 * kPi / dirs.size();
    }
    for (const auto& row : test::readCsv(test::dataDir() / "sh_projections_clamped_cosine_delta.csv")) {
        if (row[0] != "clamped_cosine_zonal") continue;
        const int l = std::stoi(row[1]);
        EXPECT_NEAR(coefficients[shIndex(l, 0)], std::stod(row[3]), 2e-4) << "l = " << l;
    }
    for (int l = 0; l < order; ++l)
        for (int m = -l; m <= l; ++m)
            if (m != 0) {
                EXPECT_NEAR(coefficients[shIndex(l, m)], 0.0, 1e-4);
            }
}

TEST(SphericalHarmonics, ProjectionRoundTripRecoversCoefficients) {
    const int order = 6, n = order * order;
    Rng rng(3, 1);
    std::vector<double> truth(n), recovered(n, 0.0), basis(n);
    for (double& c : truth) c = rng.uniform() - 0.5;
    const auto dirs = fibonacciSphere(20000);
    for (const Vec3& d : dirs) {
        const double f = reconstructSh(order, truth, d);
        evaluateSh(order, d, basis);
        for (int k = 0; k < n; ++k) recovered[k] += f * basis[k] * 4 * kPi / dirs.size();
    }
    for (int k = 0; k < n; ++k) EXPECT_NEAR(recovered[k], truth[k], 2e-3);
}

TEST(SphericalHarmonics, FiniteAtThePoles) {
    std::vector<double> basis(kMaxShOrder * kMaxShOrder);
    for (const Vec3& d : {Vec3(0, 0, 1), Vec3(0, 0, -1)}) {
        evaluateSh(kMaxShOrder, d, basis);
        for (double v : basis) EXPECT_TRUE(std::isfinite(v));
        // At the poles only m = 0 survives: Y_l0(+-z) = (+-1)^l sqrt((2l+1)/(4 pi)).
        for (int l = 0; l < kMaxShOrder; ++l)
            EXPECT_NEAR(basis[shIndex(l, 0)], std::pow(d.z, l) * std::sqrt((2 * l + 1) / (4 * kPi)), 1e-9);
    }
}

}  // namespace
}  // namespace lucent
