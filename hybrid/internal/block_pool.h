#pragma once
// The discrete ordinates' volumes streamed through a device pool (thesis
// 5.2.2 and 5.3.4): the grid is cut into blocks (32^3 by default), every
// block's volumes live in host memory, and a fixed number of device slots
// hold the blocks being worked on. An octant's sweep visits the blocks in a
// precomputed order (block wavefronts, each block after its upwind
// neighbours), so a grid whose volumes exceed the device still sweeps, at the
// cost of the copies. Slots are taken back by the thesis's not-recently-used
// policy: a free slot first, then a clean block not used in the current
// wavefront, then a dirty one, then one in use.
#include <array>
#include <cstddef>
#include <filesystem>
#include <vector>

#include "hybrid/internal/cl_device.h"
#include "hybrid/internal/host_blocks.h"

namespace lucent::hybrid {

// A grid of `dims` cut into blocks of `edge` voxels a side (the last along
// each axis smaller). Each block keeps its voxels in the grid's own order
// (x fastest), counted from its corner.
class BlockTiling {
public:
    BlockTiling(const std::array<int, 3>& dims, int edge);

    int blocks() const { return count_[0] * count_[1] * count_[2]; }
    int edge() const { return edge_; }
    const std::array<int, 3>& counts() const { return count_; }
    std::array<int, 3> coords(int b) const;
    // The block at block coordinates c, or -1 past the grid.
    int at(const std::array<int, 3>& c) const;
    // Block b is the box [lo(b), hi(b)) of the grid (core/grid_index.h's boxOf).
    std::array<int, 3> lo(int b) const;
    std::array<int, 3> hi(int b) const;
    std::array<int, 3> dims(int b) const;
    size_t voxels(int b) const;
    // The largest block's dimensions.
    std::array<int, 3> maxDims() const;
    // An octant's sweep order (octant bits 1, 2, 4: x, y, z run downwards): the
    // block wavefronts, each the blocks whose coordinates counted along the
    // sweep sum to one value. A block's upwind neighbours are all in earlier
    // wavefronts, and the blocks of one wavefront are independent.
    std::vector<std::vector<int>> wavefronts(int octant) const;

private:
    std::array<int, 3> dims_, count_;
    int edge_;
};

// Its copies are queued without waiting: the queue is in order, and the host
// reads or writes its blocks only once the queue has finished.
class BlockPool {
public:
    // volumeBytes: per voxel, each volume's size (0: the volume is not used);
    // slots: how many blocks the device holds at once (at most every block).
    // When it holds every block, nothing is ever taken back: the host keeps
    // no copies, and a volume set while resident goes straight to the device.
    // spillTo: a directory to keep the host's copies in (host_blocks.h); empty: memory.
    BlockPool(const cl::Context& context, const BlockTiling& tiling, std::vector<size_t> volumeBytes, int slots,
              const std::filesystem::path& spillTo = {});
    // Whether the host's copies went to a file.
    bool spilled() const { return host_.spilled(); }

    // Waits for the copies still queued into the host's blocks.
    ~BlockPool();
    BlockPool(const BlockPool&) = delete;
    BlockPool& operator=(const BlockPool&) = delete;

    int slots() const { return int(slots_.size()); }
    bool holdsAll() const { return slots() == tiling_.blocks(); }

    // Block b resident, with the volumes in `need` (bit v: volume v) current on
    // the device and those in `replaced` to be overwritten whole by the caller
    // (not copied up). Returns its slot. Marks it used in this wavefront.
    int acquire(const cl::CommandQueue& queue, int b, unsigned need, unsigned replaced = 0);
    cl::Buffer& buffer(int slot, int volume) { return slots_[slot].buffers[volume]; }
    // The caller wrote these volumes of the slot's block on the device.
    void written(int slot, unsigned volumes) { slots_[slot].dirty |= volumes; }
    // A new block wavefront: the used marks are cleared.
    void newWavefront();
    // Block b's volume v from `values` (the block's order).
    void set(const cl::CommandQueue& queue, int b, int volume, const void* values);
    // Block b's volume v, from wherever it is current.
    void get(const cl::CommandQueue& queue, int b, int volume, void* values);
    // Two volumes of one size exchange their roles in every block.
    void swapVolumes(int a, int c);

    struct Traffic {
        size_t uploads = 0, writeBacks = 0;  // volumes copied to and from the device
        double bytesUp = 0, bytesDown = 0;
    };
    const Traffic& traffic() const { return traffic_; }

private:
    struct Slot {
        int block = -1;
        unsigned valid = 0, dirty = 0;  // volumes current on the device; written there since
        bool used = false;              // in this wavefront (the not-recently-used mark)
        std::vector<cl::Buffer> buffers;
    };
    size_t bytesOf(int b, int volume) const { return tiling_.voxels(b) * volumeBytes_[volume]; }
    // Where the host keeps block b's volume.
    char* hostOf(int b, int volume);
    int victim();
    void writeBack(const cl::CommandQueue& queue, Slot& slot, unsigned volumes);

    BlockTiling tiling_;
    std::vector<size_t> volumeBytes_;
    std::vector<Slot> slots_;
    std::vector<int> slotOf_;       // per block, or -1
    HostBlocks host_;               // the host's copies; none when the pool holds every block
    std::vector<size_t> offset_;    // where each block's volumes start in host_
    std::vector<int> place_;        // per volume, the volume whose place in each block it has (swapVolumes)
    std::vector<unsigned> stored_;  // per block, the volumes the host holds (the others are zeros)
    int hand_ = 0;                  // where the search for a victim starts
    cl::CommandQueue queue_;        // the one copies were last queued on
    Traffic traffic_;
};

}  // namespace lucent::hybrid
