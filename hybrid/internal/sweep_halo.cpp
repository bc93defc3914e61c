#include "hybrid/internal/sweep_halo.h"

#include <algorithm>
#include <limits>
#include <string>

#include "core/error.h"
#include "core/grid_index.h"
#include "hybrid/internal/dom_solver.h"

namespace lucent::hybrid {

namespace {

// Blocks of z per pipeline stage: a sweep crosses px + py - 1 ranks, the last
// starting px + py - 2 blocks after the first, so that with this many blocks
// per stage the ranks idle about 1 / (1 + kBlocksPerStage) of a sweep.
constexpr int kBlocksPerStage = 8;

}  // namespace

SweepPartition partitionSweeps(const std::array<int, 3>& cells, int rank, int ranks) {
    SweepPartition p;
    // The least face area between the ranks: nz (ny (px - 1) + nx (py - 1)).
    double best = std::numeric_limits<double>::infinity();
    for (int px = 1; px <= ranks; ++px) {
        if (ranks % px != 0) continue;
        const int py = ranks / px;
        if (px > cells[0] || py > cells[1]) continue;
        const double area = double(cells[1]) * (px - 1) + double(cells[0]) * (py - 1);
        if (area < best) best = area, p.ranks = {px, py};
    }
    if (!(best < std::numeric_limits<double>::infinity()))
        throw Error(std::to_string(ranks) + " ranks cannot share " + std::to_string(cells[0]) + "x" +
                    std::to_string(cells[1]) + " columns of cells: each rank needs one at least");
    const int at[2] = {rank % p.ranks[0], rank / p.ranks[0]};
    for (int a = 0; a < 2; ++a) {
        p.lo[a] = int(int64_t(cells[a]) * at[a] / p.ranks[a]);
        p.hi[a] = int(int64_t(cells[a]) * (at[a] + 1) / p.ranks[a]);
        const int stride = a == 0 ? 1 : p.ranks[0];
        if (at[a] > 0) p.neighbour[2 * a] = rank - stride;
        if (at[a] + 1 < p.ranks[a]) p.neighbour[2 * a + 1] = rank + stride;
    }
    p.hi[2] = cells[2];
    return p;
}

int sweepBlocks(const SweepPartition& part) {
    const bool shared = part.ranks[0] * part.ranks[1] > 1;
    return shared ? std::clamp(kBlocksPerStage * (part.ranks[0] + part.ranks[1] - 2), 1, part.dims()[2]) : 1;
}

std::vector<glm::vec4> gatherShares(const std::array<int, 3>& cells, std::vector<glm::vec4> mine, size_t perCell,
                                    const Peers& peers) {
    if (peers.size() == 1) return mine;
    if (peers.rank() != 0) {
        peers.send(0, &mine[0].x, mine.size() * 4);
        return {};
    }
    std::vector<glm::vec4> all(GridIndex{cells}.count() * perCell);
    for (int r = 0; r < peers.size(); ++r) {
        const SweepPartition share = partitionSweeps(cells, r, peers.size());
        std::vector<glm::vec4> theirs;
        if (r == 0) {
            theirs = std::move(mine);
        } else {
            theirs.resize(GridIndex{share.dims()}.count() * perCell);
            peers.receive(r, &theirs[0].x, theirs.size() * 4);
        }
        putBox(all, cells, share.lo, share.hi, theirs, perCell);
    }
    return all;
}

SweepHalo::SweepHalo(const Peers& peers, const SweepPartition& part, int directions)
    : peers_(peers), part_(part), directions_(directions), perOctant_(directions / 8) {
    for (int f = 0; f < 6; ++f)
        if (part.neighbour[f] >= 0) mask_ |= 1 << f;
    blocks_ = sweepBlocks(part);
}

std::array<int, 2> SweepHalo::block(int b) const {
    const int nz = part_.dims()[2];
    return {int(int64_t(nz) * b / blocks_), int(int64_t(nz) * (b + 1) / blocks_)};
}

std::array<size_t, 2> SweepHalo::faceCells(int face, int octant, int b) const {
    const std::array<int, 3> d = part_.dims();
    const std::array<int, 2> k = block(b);
    // The block counts z in the sweep's direction; the buffers, from z = 0.
    const bool down = (octant >> 2) & 1;
    const int first = down ? d[2] - k[1] : k[0];
    const size_t row = face < 2 ? size_t(d[1]) : size_t(d[0]);  // x faces hold (y, z), y faces (x, z)
    return {row * first, row * size_t(k[1] - k[0])};
}

void SweepHalo::receive(cl::CommandQueue& queue, cl::Buffer& in, int octant, int b) {
    const int faces[2] = {octant & 1, 2 + ((octant >> 1) & 1)};  // entered by: x-/x+, y-/y+
    for (const int f : faces) {
        if (part_.neighbour[f] < 0) continue;
        const auto [first, count] = faceCells(f, octant, b);
        packed_.resize(count * perOctant_);
        peers_.receive(part_.neighbour[f], &packed_[0].x, packed_.size() * 4);
        wide_.assign(count * directions_, glm::vec4(0.0f));
        for (size_t c = 0; c < count; ++c)
            std::copy_n(&packed_[c * perOctant_], perOctant_, &wide_[c * directions_ + octant * perOctant_]);
        const size_t at = DomSolver::faceOffset(f, part_.dims(), directions_) + first * directions_;
        queue.enqueueWriteBuffer(in, CL_TRUE, at * sizeof(glm::vec4), wide_.size() * sizeof(glm::vec4), wide_.data());
    }
}

void SweepHalo::send(cl::CommandQueue& queue, cl::Buffer& out, int octant, int b) {
    const int faces[2] = {(octant & 1) ^ 1, (2 + ((octant >> 1) & 1)) ^ 1};  // left by
    for (const int f : faces) {
        if (part_.neighbour[f] < 0) continue;
        const auto [first, count] = faceCells(f, octant, b);
        wide_.resize(count * directions_);
        const size_t at = DomSolver::faceOffset(f, part_.dims(), directions_) + first * directions_;
        queue.enqueueReadBuffer(out, CL_TRUE, at * sizeof(glm::vec4), wide_.size() * sizeof(glm::vec4), wide_.data());
        packed_.resize(count * perOctant_);
        for (size_t c = 0; c < count; ++c)
            std::copy_n(&wide_[c * directions_ + octant * perOctant_], perOctant_, &packed_[c * perOctant_]);
        peers_.send(part_.neighbour[f], &packed_[0].x, packed_.size() * 4);
        sent_ += double(packed_.size() * sizeof(glm::vec4));
    }
}

}  // namespace lucent::hybrid
