#include "hybrid/internal/host_blocks.h"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/statvfs.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <string>
#include <utility>

#include "core/error.h"

namespace lucent::hybrid {

namespace {

std::string mib(size_t bytes) { return std::to_string((bytes + (1 << 20) - 1) >> 20) + " MiB"; }

}  // namespace

HostBlocks::HostBlocks(size_t bytes, const std::filesystem::path& spillTo) : bytes_(std::max<size_t>(bytes, 1)) {
    int flags = MAP_PRIVATE | MAP_ANONYMOUS | MAP_NORESERVE;
    if (!spillTo.empty()) {
        const std::string where = "the device pool's blocks (" + mib(bytes_) + ") cannot spill to " + spillTo.string();
        struct statvfs disk {};
        if (statvfs(spillTo.c_str(), &disk) != 0) throw Error(where + ": " + std::strerror(errno));
        const double free = double(disk.f_bavail) * double(disk.f_frsize);
        if (free < double(bytes_)) throw Error(where + ": the disk has " + mib(size_t(free)) + " free");
        // An unnamed file (O_TMPFILE): nothing to clean up, nothing another
        // process can open. Where the file system cannot make one, a file
        // named by mkstemp and unlinked at once.
        fd_ = open(spillTo.c_str(), O_TMPFILE | O_RDWR | O_EXCL | O_CLOEXEC, 0600);
        if (fd_ < 0 && (errno == EOPNOTSUPP || errno == EISDIR || errno == EINVAL)) {
            std::string name = (spillTo / "lucent-blocks-XXXXXX").string();
            fd_ = mkostemp(name.data(), O_CLOEXEC);
            if (fd_ >= 0) unlink(name.c_str());
        }
        if (fd_ < 0) throw Error(where + ": " + std::strerror(errno));
        if (ftruncate(fd_, off_t(bytes_)) != 0) {
            const int e = errno;
            release();
            throw Error(where + ": " + std::strerror(e));
        }
        flags = MAP_SHARED;
    }
    void* p = mmap(nullptr, bytes_, PROT_READ | PROT_WRITE, flags, fd_, 0);
    if (p == MAP_FAILED) {
        const int e = errno;
        release();
        throw Error("the device pool's blocks (" + mib(bytes_) + ") cannot be mapped: " + std::strerror(e));
    }
    data_ = static_cast<char*>(p);
}

HostBlocks::~HostBlocks() { release(); }

HostBlocks::HostBlocks(HostBlocks&& other) noexcept
    : data_(std::exchange(other.data_, nullptr)),
      bytes_(std::exchange(other.bytes_, 0)),
      fd_(std::exchange(other.fd_, -1)) {}

HostBlocks& HostBlocks::operator=(HostBlocks&& other) noexcept {
    if (this != &other) {
        release();
        data_ = std::exchange(other.data_, nullptr);
        bytes_ = std::exchange(other.bytes_, 0);
        fd_ = std::exchange(other.fd_, -1);
    }
    return *this;
}

void HostBlocks::release() {
    if (data_) munmap(data_, bytes_);
    if (fd_ >= 0) close(fd_);
    data_ = nullptr;
    fd_ = -1;
}

}  // namespace lucent::hybrid
