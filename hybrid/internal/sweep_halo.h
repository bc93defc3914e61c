#pragma once
// The discrete ordinates sweeps shared among the ranks of an MPI job, KBA
// style (Baker and Koch's wavefront decomposition, as in Denovo, PDT and
// OpenSn): the ranks form a 2-D grid over x and y, each holding a column of
// cells through all of z. An octant's sweep is pipelined in blocks of z: a
// rank sweeps a block once the ranks upstream in x and y have sent the
// radiance leaving their faces for it, and sends its own downstream. The
// radiance crossing a rank's face is the very float4 one process would carry
// across that face, so the flux does not depend on the number of ranks.
#include <array>
#include <vector>

#include <glm/glm.hpp>

#include "core/peers.h"
#include "hybrid/internal/cl_device.h"

namespace lucent::hybrid {

// One rank's share of a grid of `cells`.
struct SweepPartition {
    std::array<int, 2> ranks{1, 1};  // the process grid over x and y
    std::array<int, 3> lo{0, 0, 0};  // this rank's cells, [lo, hi)
    std::array<int, 3> hi{0, 0, 0};
    std::array<int, 6> neighbour{-1, -1, -1, -1, -1, -1};  // the rank across x-, x+, y-, y+, z-, z+; -1: the box's face
    std::array<int, 3> dims() const { return {hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]}; }
};

// The process grid with the least face area between ranks, and rank's share of
// it. Throws Error when there are more ranks than columns of cells.
SweepPartition partitionSweeps(const std::array<int, 3>& cells, int rank, int ranks);

// How many blocks of z each octant's sweep is pipelined in on this share.
int sweepBlocks(const SweepPartition& part);

// Every rank's share of a grid of `cells` (perCell values a cell, in the
// share's own order) put together on rank 0; the others get nothing back.
std::vector<glm::vec4> gatherShares(const std::array<int, 3>& cells, std::vector<glm::vec4> mine, size_t perCell,
                                    const Peers& peers);

// The exchange of one rank's faces during the sweeps.
class SweepHalo {
public:
    // part: this rank's share; directions: N.
    SweepHalo(const Peers& peers, const SweepPartition& part, int directions);

    // Faces whose in-coming radiance a neighbour sends, as a mask (bit f for face f).
    int mask() const { return mask_; }
    // How many blocks of z each octant's sweep is pipelined in.
    int blocks() const { return blocks_; }
    // The sweep-ordered z range of block b: [first, last).
    std::array<int, 2> block(int b) const;
    // Before block b of an octant's sweep: what the upstream neighbours' faces
    // sent, into `in` (laid out as the boundary buffers, DomSolver::faceOffset).
    void receive(cl::CommandQueue& queue, cl::Buffer& in, int octant, int b);
    // After it: this rank's out-going radiance (the boundary buffer the sweep
    // wrote) to the downstream neighbours.
    void send(cl::CommandQueue& queue, cl::Buffer& out, int octant, int b);
    // Values summed over the ranks.
    void sum(double* values, int count) const { peers_.sum(values, count); }
    // Bytes this rank has sent so far.
    double bytesSent() const { return sent_; }

private:
    // The boundary buffer's cells of face f in block b: the first and the count.
    std::array<size_t, 2> faceCells(int face, int octant, int b) const;

    const Peers& peers_;
    SweepPartition part_;
    int directions_, perOctant_;
    int mask_ = 0, blocks_ = 1;
    double sent_ = 0;
    std::vector<glm::vec4> wide_, packed_;  // a face's cells with all N directions, and one octant's K
};

}  // namespace lucent::hybrid
