// The uncollided flux moments integrated cell to cell (hybrid/internal/
// uncollided_flux.h) against a brute-force average over point pairs: every
// moment, in every direction from the source, near and far. No OpenCL.
#include <gtest/gtest.h>

#include <cmath>

#include "core/spherical_harmonics.h"
#include "hybrid/internal/uncollided_flux.h"

namespace lucent::hybrid {
namespace {

constexpr int kBands = 3;

// The average over target cell t of the uncollided flux moments of a unit
// source density filling cell s, in a uniform medium of extinction sigma:
//   1/V int_t int_s e^{-sigma r} / (4 pi r^2) Y_m((x - y) / r) dy dx
// by the midpoint rule on n^3 points in each cell (the cells at least a cell
// apart, the integrand smooth).
std::vector<double> bruteForce(const std::array<int, 3>& t, const std::array<int, 3>& s, const Vec3& h, double sigma) {
    constexpr int n = 10;
    const int moments = kBands * kBands;
    std::vector<double> sum(moments, 0.0), y(moments);
    auto point = [&](const std::array<int, 3>& c, int i) {
        return Vec3(c[0] + (i % n + 0.5) / n, c[1] + (i / n % n + 0.5) / n, c[2] + (i / (n * n) + 0.5) / n) * h;
    };
    for (int i = 0; i < n * n * n; ++i)
        for (int j = 0; j < n * n * n; ++j) {
            const Vec3 u = point(t, i) - point(s, j);
            const double r = glm::length(u);
            evaluateSh(kBands, u / r, y);
            for (int m = 0; m < moments; ++m) sum[m] += std::exp(-sigma * r) / (4.0 * kPi * r * r) * y[m];
        }
    const double volume = h.x * h.y * h.z, pairs = double(n * n * n) * (n * n * n);
    for (double& v : sum) v *= volume / pairs;  // 1/V * V_t * V_s / pairs
    return sum;
}

TEST(UncollidedFlux, EveryMomentMatchesTheAverageOverPointPairs) {
    // One source cell in a 15 x 13 x 11 grid of unequal edges; targets near
    // (the exact kernel, mirrored into every octant) and far (the point kernel
    // with its optical depth traced), in a uniform medium.
    DomGrid grid;
    grid.dims = {15, 13, 11};
    grid.edges = Vec3(0.2, 0.25, 0.3);
    const double sigma = 1.5;
    grid.extinction.assign(grid.count(), glm::vec4(glm::vec3(float(sigma)), 1.0f));
    const std::array<int, 3> s{7, 6, 5};
    std::vector<double> source(grid.count(), 0.0);
    source[s[0] + 15 * (s[1] + 13 * s[2])] = 2.0;
    const std::vector<glm::vec4> flux = uncollidedFlux(grid, source, kBands, {});
    const std::array<int, 3> targets[] = {{9, 6, 5}, {5, 7, 5}, {7, 3, 7}, {6, 5, 3}, {4, 9, 8}, {14, 6, 5}, {0, 0, 0}};
    for (const auto& t : targets) {
        const std::vector<double> truth = bruteForce(t, s, grid.edges, sigma);
        const size_t v = t[0] + 15 * (t[1] + 13 * size_t(t[2]));
        // Every moment within the 2% the transport results are held to
        // (discrete_ordinates_test.cpp), of the moment or, where it passes
        // near zero, of the scalar one.
        const double share = 0.02;
        for (int m = 0; m < kBands * kBands; ++m)
            EXPECT_NEAR(flux[v * kBands * kBands + m].r, 2.0 * truth[m],
                        share * 2.0 * std::max(std::abs(truth[m]), std::abs(truth[0])))
                << "target " << t[0] << "," << t[1] << "," << t[2] << " moment " << m;
    }
}

TEST(UncollidedFlux, ChannelsAttenuateByTheirOwnExtinction) {
    // Red through vacuum, green and blue through thicker media: each channel's
    // flux falls as its own e^{-sigma r}, near and far.
    DomGrid grid;
    grid.dims = {12, 3, 3};
    grid.edges = Vec3(0.5);
    grid.extinction.assign(grid.count(), glm::vec4(0.0f, 0.5f, 2.0f, 1.0f));
    std::vector<double> source(grid.count(), 0.0);
    source[0 + 12 * (1 + 3 * 1)] = 1.0;
    const std::vector<glm::vec4> flux = uncollidedFlux(grid, source, 1, {});
    for (const std::array<int, 3> t : {std::array<int, 3>{2, 1, 1}, std::array<int, 3>{10, 1, 1}}) {
        const size_t v = t[0] + 12 * (1 + 3 * 1);
        for (int c = 0; c < 3; ++c) {
            const double sigma = c == 0 ? 0.0 : c == 1 ? 0.5 : 2.0;
            const double truth = bruteForce(t, {0, 1, 1}, grid.edges, sigma)[0];
            EXPECT_NEAR(flux[v][c], truth, 0.02 * truth) << "target " << t[0] << " channel " << c;
        }
    }
}

TEST(UncollidedFlux, AReflectiveFaceGivesTheFluxOfTheSymmetricProblem) {
    // Sources in a corner of a grid whose x- and z+ faces reflect, in a
    // heterogeneous medium, against the grid unfolded across both faces (4
    // times as many cells, the sources and the medium mirrored), vacuum all
    // round: inside the first, both must give the same moments, near and far.
    const std::array<int, 3> dims{6, 5, 4};
    auto sigmaAt = [](int i, int j, int k) { return 0.3f + 0.2f * float((i + 2 * j + 3 * k) % 4); };
    DomGrid folded;
    folded.dims = dims;
    folded.edges = Vec3(0.5, 0.4, 0.6);
    folded.extinction.resize(folded.count());
    std::vector<double> source(folded.count(), 0.0);
    for (size_t v = 0; v < folded.count(); ++v) {
        const auto c = folded.index().cell(v);
        folded.extinction[v] = glm::vec4(glm::vec3(sigmaAt(c[0], c[1], c[2])), 1.0f);
        if (c[0] < 2 && c[1] < 2 && c[2] >= 2) source[v] = 1.0 + c[1];
    }
    DomGrid unfolded;
    unfolded.dims = {12, 5, 8};  // x mirrored below 0, z above 4
    unfolded.edges = folded.edges;
    unfolded.extinction.resize(unfolded.count());
    std::vector<double> mirrored(unfolded.count(), 0.0);
    auto foldOf = [&](const std::array<int, 3>& u) {  // unfolded cell -> folded cell
        const int i = u[0] < 6 ? 5 - u[0] : u[0] - 6, k = u[2] < 4 ? u[2] : 7 - u[2];
        return std::array<int, 3>{i, u[1], k};
    };
    for (size_t v = 0; v < unfolded.count(); ++v) {
        const auto f = foldOf(unfolded.index().cell(v));
        unfolded.extinction[v] = folded.extinction[folded.index()(f)];
        mirrored[v] = source[folded.index()(f)];
    }
    const std::vector<glm::vec4> a = uncollidedFlux(folded, source, kBands, {true, false, false, false, false, true});
    const std::vector<glm::vec4> b = uncollidedFlux(unfolded, mirrored, kBands, {});
    const int moments = kBands * kBands;
    for (size_t v = 0; v < folded.count(); ++v) {
        const auto c = folded.index().cell(v);
        const size_t u = unfolded.index()({c[0] + 6, c[1], c[2]});
        for (int m = 0; m < moments; ++m)
            EXPECT_NEAR(a[v * moments + m].r, b[u * moments + m].r, 1e-4 * std::abs(b[u * moments].r))
                << "cell " << c[0] << "," << c[1] << "," << c[2] << " moment " << m;
    }
}

}  // namespace
}  // namespace lucent::hybrid
