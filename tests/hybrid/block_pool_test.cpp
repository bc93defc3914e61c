// The discrete ordinates' volumes streamed through a device pool of blocks
// (block_pool.h, thesis 5.2.2 and 5.3.4): the block order keeps every block
// after its upwind neighbours, and the flux swept through a pool of a few
// blocks is the flux of the whole grid held on the device, to float rounding
// (the sweeps carry across each block's faces the very float4 one grid
// carries, so only the order of the convergence sums differs).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numeric>

#include "core/spherical_harmonics.h"
#include "core/error.h"
#include "core/grid_index.h"
#include "hybrid/internal/block_pool.h"
#include "hybrid/internal/host_blocks.h"
#include "hybrid/internal/cl_device.h"
#include "hybrid/internal/dom_solver.h"
#include "hybrid/ordinates.h"

namespace lucent::hybrid {
namespace {

ClDevice& device() {
    static ClDevice d;
    return d;
}

TEST(BlockPool, EveryBlockComesAfterItsUpwindNeighbours) {
    const BlockTiling tiling({20, 17, 23}, 8);
    ASSERT_EQ(tiling.blocks(), 3 * 3 * 3);
    EXPECT_EQ(tiling.dims(tiling.at({2, 2, 2})), (std::array<int, 3>{4, 1, 7}));
    for (int octant = 0; octant < 8; ++octant) {
        std::vector<int> wavefront(tiling.blocks(), -1);
        const auto order = tiling.wavefronts(octant);
        for (size_t w = 0; w < order.size(); ++w)
            for (int b : order[w]) {
                EXPECT_EQ(wavefront[b], -1) << "block " << b << " twice";
                wavefront[b] = int(w);
            }
        for (int b = 0; b < tiling.blocks(); ++b) {
            ASSERT_GE(wavefront[b], 0) << "block " << b << " never swept";
            for (int a = 0; a < 3; ++a) {
                std::array<int, 3> up = tiling.coords(b);
                up[a] += (octant >> a) & 1 ? 1 : -1;
                const int u = tiling.at(up);
                if (u < 0) continue;
                EXPECT_LT(wavefront[u], wavefront[b]) << "octant " << octant << " axis " << a;
            }
        }
    }
}

TEST(BlockPool, BlocksHoldTheGridsValuesInTheirOwnOrder) {
    const std::array<int, 3> dims{11, 6, 9};
    const BlockTiling tiling(dims, 4);
    std::vector<int> grid(size_t(dims[0]) * dims[1] * dims[2]), back(grid.size(), -1);
    std::iota(grid.begin(), grid.end(), 0);
    size_t seen = 0;
    for (int b = 0; b < tiling.blocks(); ++b) {
        const auto lo = tiling.lo(b), d = tiling.dims(b);
        const std::vector<int> block = boxOf(grid, dims, lo, tiling.hi(b));
        ASSERT_EQ(block.size(), tiling.voxels(b));
        // The block's first and last voxels are its corners in the grid.
        EXPECT_EQ(block.front(), lo[0] + dims[0] * (lo[1] + dims[1] * lo[2]));
        EXPECT_EQ(block.back(), lo[0] + d[0] - 1 + dims[0] * (lo[1] + d[1] - 1 + dims[1] * (lo[2] + d[2] - 1)));
        putBox(back, dims, lo, tiling.hi(b), block);
        seen += block.size();
    }
    EXPECT_EQ(seen, grid.size());
    EXPECT_EQ(back, grid);
}

// A ball of refracting, forward-scattering medium in a box of air, glowing in
// a few voxels near one side: its total flux after six generations and a tail.
struct Solve {
    std::vector<glm::vec4> flux;
    BlockPool::Traffic traffic;
};

Solve solveBall(const DomPool& pool) {
    DomGrid grid;
    grid.dims = {20, 17, 23};
    grid.edges = Vec3(0.1);
    const GridIndex index = grid.index();
    const size_t voxels = index.count();
    grid.extinction.assign(voxels, glm::vec4(0.0f));
    grid.scattering.assign(voxels, glm::vec4(0.0f));
    grid.phase.assign(voxels, glm::vec4(0.5f, 0.0f, 0.0f, 0.0f));
    grid.boundaryNormal.assign(voxels, glm::vec3(0.0f));
    grid.ior = 1.4;
    const glm::vec3 centre(10.0f, 8.5f, 11.5f);
    for (int k = 0; k < grid.dims[2]; ++k)
        for (int j = 0; j < grid.dims[1]; ++j)
            for (int i = 0; i < grid.dims[0]; ++i) {
                const glm::vec3 r = glm::vec3(i + 0.5f, j + 0.5f, k + 0.5f) - centre;
                const size_t v = index(i, j, k);
                grid.boundaryNormal[v] = glm::length(r) > 0.0f ? glm::normalize(r) : glm::vec3(0.0f);
                if (glm::length(r) > 7.5f) continue;
                grid.extinction[v] = glm::vec4(8.0f, 12.0f, 20.0f, 1.0f);
                grid.scattering[v] = glm::vec4(7.2f, 9.6f, 14.0f, 0.0f);
            }
    const int bands = 3, moments = bands * bands;
    DomSolver solver(device(), grid, 48, bands, {}, nullptr, pool);
    std::vector<glm::vec4> source(voxels * moments, glm::vec4(0.0f));
    std::vector<double> y(moments);
    evaluateSh(bands, glm::normalize(Vec3(1, 0.3, 0.2)), y);
    for (int i = 4; i < 7; ++i)
        for (int m = 0; m < moments; ++m) source[index(i, 8, 11) * moments + m] = glm::vec4(glm::vec3(float(y[m])), 0);
    cl::CommandQueue& queue = device().marchQueue;
    solver.setSource(queue, source);
    for (int it = 0; it < 6; ++it) solver.iterate(queue);
    solver.addTail(queue, Rgb(0.5, 0.8, 1.5));
    return {solver.totalFlux(queue), solver.traffic()};
}

TEST(BlockPool, SweepsThroughAFewBlocksGiveTheWholeGridsFlux) {
    const Solve whole = solveBall({});
    const Solve half = solveBall({0.5, 8});  // 27 blocks of 8^3, 14 on the device
    const Solve few = solveBall({0.05, 8});  // 2 of them
    // The host's blocks in an unnamed file of the temporary directory.
    const Solve spilled = solveBall({0.05, 8, std::filesystem::temp_directory_path()});
    double largest = 0.0;
    for (const glm::vec4& f : whole.flux) largest = std::max(largest, double(glm::length(glm::vec3(f))));
    ASSERT_GT(largest, 0.0);
    for (const Solve* s : {&half, &few, &spilled}) {
        ASSERT_EQ(s->flux.size(), whole.flux.size());
        double worst = 0.0;
        for (size_t i = 0; i < whole.flux.size(); ++i)
            worst = std::max(worst, double(glm::length(glm::vec3(s->flux[i] - whole.flux[i]))));
        EXPECT_LE(worst, 1e-5 * largest) << (s == &half ? "50% pool" : s == &few ? "5% pool" : "spilled");
    }
    // Holding 2 of 27 blocks, each octant streams every block in and its flux out.
    EXPECT_GT(few.traffic.writeBacks, size_t(6 * 8 * 27));
    EXPECT_LT(half.traffic.bytesUp, few.traffic.bytesUp);
}

TEST(BlockPool, HoldingEveryBlockIsTheWholeGrid) {
    // 8 blocks of 32^3: a share of 0.9 is ceil(7.2) = 8 of them, 0.85 is 7.
    EXPECT_FALSE(DomSolver::pooled({64, 64, 64}, {1.0}));
    EXPECT_FALSE(DomSolver::pooled({64, 64, 64}, {0.9}));
    EXPECT_TRUE(DomSolver::pooled({64, 64, 64}, {0.85}));
    EXPECT_EQ(DomSolver::slotsFor({64, 64, 64}, {0.85}), 7);
    EXPECT_EQ(DomSolver::slotsFor({128, 128, 128}, {0.05}), 4);  // of 64
    EXPECT_EQ(DomSolver::slotsFor({128, 128, 128}, {1e-9}), 1);  // one block at least
    EXPECT_EQ(DomSolver::hostBytesFor({64, 64, 64}, 4, {1.0}, true), 0u);
    // Pooled, per voxel: three float4 materials and four volumes of 16 float4
    // moments (source, flux, last flux, total), and a refracting object's six
    // inner faces (an int each).
    const size_t voxels = 64 * 64 * 64;
    EXPECT_EQ(DomSolver::hostBytesFor({64, 64, 64}, 4, {0.5}, false), voxels * (3 * 16 + 4 * 16 * 16));
    EXPECT_EQ(DomSolver::hostBytesFor({64, 64, 64}, 4, {0.5}, true), voxels * (3 * 16 + 4 * 16 * 16 + 6 * 4));
}

TEST(BlockPool, SpillingWhereNoFileCanBeMadeIsOneClearError) {
    try {
        HostBlocks blocks(1 << 20, "/nonexistent-lucent-directory");
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("/nonexistent-lucent-directory"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace lucent::hybrid
