#pragma once
// The host's copies of a device pool's blocks (block_pool.h): one mapping,
// zeros until written. In anonymous memory, or spilled to an unnamed file in
// a directory: the kernel then writes its pages out under memory pressure
// and reads them back on use, so that blocks larger than the machine's memory
// still run, at the disk's speed. The file has no name and goes with the
// mapping, also when the process dies.
#include <cstddef>
#include <filesystem>

namespace lucent::hybrid {

class HostBlocks {
public:
    HostBlocks() = default;
    // spillTo empty: anonymous memory. Throws Error naming the directory when
    // the file cannot be made or the disk has less than `bytes` free.
    HostBlocks(size_t bytes, const std::filesystem::path& spillTo);
    ~HostBlocks();
    HostBlocks(HostBlocks&& other) noexcept;
    HostBlocks& operator=(HostBlocks&& other) noexcept;
    HostBlocks(const HostBlocks&) = delete;
    HostBlocks& operator=(const HostBlocks&) = delete;

    char* data() { return data_; }
    size_t size() const { return bytes_; }
    bool spilled() const { return fd_ >= 0; }

private:
    void release();
    char* data_ = nullptr;
    size_t bytes_ = 0;
    int fd_ = -1;
};

}  // namespace lucent::hybrid
