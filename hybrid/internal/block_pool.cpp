#include "hybrid/internal/block_pool.h"

#include <algorithm>
#include <cstring>

#include "core/error.h"

namespace lucent::hybrid {

BlockTiling::BlockTiling(const std::array<int, 3>& dims, int edge) : dims_(dims), edge_(edge) {
    if (edge < 1) throw Error("internal: blocks of " + std::to_string(edge) + " voxels");
    for (int a = 0; a < 3; ++a) count_[a] = std::max(1, (dims[a] + edge - 1) / edge);
}

std::array<int, 3> BlockTiling::coords(int b) const {
    return {b % count_[0], b / count_[0] % count_[1], b / (count_[0] * count_[1])};
}

int BlockTiling::at(const std::array<int, 3>& c) const {
    for (int a = 0; a < 3; ++a)
        if (c[a] < 0 || c[a] >= count_[a]) return -1;
    return c[0] + count_[0] * (c[1] + count_[1] * c[2]);
}

std::array<int, 3> BlockTiling::lo(int b) const {
    const std::array<int, 3> c = coords(b);
    return {c[0] * edge_, c[1] * edge_, c[2] * edge_};
}

std::array<int, 3> BlockTiling::hi(int b) const {
    const std::array<int, 3> l = lo(b), d = dims(b);
    return {l[0] + d[0], l[1] + d[1], l[2] + d[2]};
}

std::array<int, 3> BlockTiling::dims(int b) const {
    const std::array<int, 3> l = lo(b);
    return {std::min(edge_, dims_[0] - l[0]), std::min(edge_, dims_[1] - l[1]), std::min(edge_, dims_[2] - l[2])};
}

size_t BlockTiling::voxels(int b) const {
    const std::array<int, 3> d = dims(b);
    return size_t(d[0]) * d[1] * d[2];
}

std::array<int, 3> BlockTiling::maxDims() const {
    return {std::min(edge_, dims_[0]), std::min(edge_, dims_[1]), std::min(edge_, dims_[2])};
}

std::vector<std::vector<int>> BlockTiling::wavefronts(int octant) const {
    std::vector<std::vector<int>> out(count_[0] + count_[1] + count_[2] - 2);
    for (int b = 0; b < blocks(); ++b) {
        const std::array<int, 3> c = coords(b);
        int w = 0;
        for (int a = 0; a < 3; ++a) w += (octant >> a) & 1 ? count_[a] - 1 - c[a] : c[a];
        out[w].push_back(b);
    }
    return out;
}

BlockPool::BlockPool(const cl::Context& context, const BlockTiling& tiling, std::vector<size_t> volumeBytes, int slots,
                     const std::filesystem::path& spillTo)
    : tiling_(tiling), volumeBytes_(std::move(volumeBytes)), slotOf_(tiling.blocks(), -1) {
    if (slots < 1 || slots > tiling.blocks())
        throw Error("internal: a pool of " + std::to_string(slots) + " slots for " + std::to_string(tiling.blocks()) +
                    " blocks");
    const std::array<int, 3> d = tiling.maxDims();
    const size_t voxels = size_t(d[0]) * d[1] * d[2];
    slots_.resize(slots);
    for (Slot& s : slots_)
        for (size_t bytes : volumeBytes_) s.buffers.push_back(zeroBuffer(context, voxels * bytes));
    size_t perVoxel = 0;
    for (size_t b : volumeBytes_) perVoxel += b;
    for (int b = 0; b <= tiling.blocks(); ++b)
        offset_.push_back(b == 0 ? 0 : offset_.back() + tiling.voxels(b - 1) * perVoxel);
    for (size_t v = 0; v < volumeBytes_.size(); ++v) place_.push_back(int(v));
    stored_.assign(tiling.blocks(), 0);
    if (!holdsAll()) host_ = HostBlocks(offset_.back(), spillTo);
}

BlockPool::~BlockPool() {
    try {
        if (queue_()) queue_.finish();
    } catch (const cl::Error&) {  // a device lost: nothing more will be copied either
    }
}

char* BlockPool::hostOf(int b, int volume) {
    if (!host_.data()) throw Error("internal: a pool holding every block has no host copies");
    size_t at = offset_[b];
    for (int v = 0; v < place_[volume]; ++v) at += bytesOf(b, v);
    return host_.data() + at;
}

int BlockPool::victim() {
    // The thesis's order of preference (5.2.2): free, clean and not used in
    // this wavefront, dirty and not used, and only then one in use; ties go
    // round the slots, so that no slot is always the one taken.
    auto rank = [](const Slot& s) { return s.block < 0 ? 0 : 1 + (s.used ? 2 : 0) + (s.dirty ? 1 : 0); };
    int best = -1;
    for (int i = 0; i < slots(); ++i) {
        const int s = (hand_ + i) % slots();
        if (best < 0 || rank(slots_[s]) < rank(slots_[best])) best = s;
    }
    hand_ = (best + 1) % slots();
    return best;
}

void BlockPool::writeBack(const cl::CommandQueue& queue, Slot& slot, unsigned volumes) {
    for (size_t v = 0; v < volumeBytes_.size(); ++v) {
        if (!((volumes >> v) & 1u)) continue;
        const size_t bytes = bytesOf(slot.block, int(v));
        queue.enqueueReadBuffer(slot.buffers[v], CL_FALSE, 0, bytes, hostOf(slot.block, int(v)));
        ++traffic_.writeBacks;
        traffic_.bytesDown += double(bytes);
        stored_[slot.block] |= 1u << v;
        slot.dirty &= ~(1u << v);
    }
}

int BlockPool::acquire(const cl::CommandQueue& queue, int b, unsigned need, unsigned replaced) {
    queue_ = queue;
    int s = slotOf_[b];
    if (s < 0) {
        s = victim();
        Slot& slot = slots_[s];
        if (slot.block >= 0) {
            writeBack(queue, slot, slot.dirty & slot.valid);
            slotOf_[slot.block] = -1;
        }
        slot.block = b;
        slot.valid = slot.dirty = 0;
        slotOf_[b] = s;
    }
    Slot& slot = slots_[s];
    slot.used = true;
    slot.valid |= replaced;
    const unsigned missing = need & ~slot.valid;
    for (size_t v = 0; v < volumeBytes_.size(); ++v) {
        if (!((missing >> v) & 1u) || volumeBytes_[v] == 0) continue;
        const size_t bytes = bytesOf(b, int(v));
        if ((stored_[b] >> v) & 1u)
            queue.enqueueWriteBuffer(slot.buffers[v], CL_FALSE, 0, bytes, hostOf(b, int(v)));
        else  // never stored: zeros
            queue.enqueueFillBuffer(slot.buffers[v], cl_uchar(0), 0, bytes);
        ++traffic_.uploads;
        traffic_.bytesUp += double(bytes);
        slot.valid |= 1u << v;
    }
    return s;
}

void BlockPool::newWavefront() {
    for (Slot& s : slots_) s.used = false;
}

void BlockPool::set(const cl::CommandQueue& queue, int b, int volume, const void* values) {
    const size_t bytes = bytesOf(b, volume);
    const int s = slotOf_[b];
    if (s >= 0) {
        queue.enqueueWriteBuffer(slots_[s].buffers[volume], CL_TRUE, 0, bytes, values);
        slots_[s].valid |= 1u << volume;
        slots_[s].dirty |= 1u << volume;
        return;
    }
    queue.finish();  // no copy of the queue's still reads the host's blocks
    std::memcpy(hostOf(b, volume), values, bytes);
    stored_[b] |= 1u << volume;
}

void BlockPool::get(const cl::CommandQueue& queue, int b, int volume, void* values) {
    const size_t bytes = bytesOf(b, volume);
    const int s = slotOf_[b];
    if (s >= 0 && (slots_[s].valid >> volume) & 1u)
        queue.enqueueReadBuffer(slots_[s].buffers[volume], CL_TRUE, 0, bytes, values);
    else if ((stored_[b] >> volume) & 1u) {
        queue.finish();  // the queue's copies back are in
        std::memcpy(values, hostOf(b, volume), bytes);
    } else
        std::memset(values, 0, bytes);
}

void BlockPool::swapVolumes(int a, int c) {
    if (volumeBytes_[a] != volumeBytes_[c]) throw Error("internal: swapping volumes of different sizes");
    std::swap(place_[a], place_[c]);
    auto swapBits = [&](unsigned& bits) {
        const unsigned x = (bits >> a) & 1u, y = (bits >> c) & 1u;
        bits = (bits & ~((1u << a) | (1u << c))) | (x << c) | (y << a);
    };
    for (unsigned& bits : stored_) swapBits(bits);
    for (Slot& s : slots_) {
        std::swap(s.buffers[a], s.buffers[c]);
        swapBits(s.valid);
        swapBits(s.dirty);
    }
}

}  // namespace lucent::hybrid
