#include "core/atomic_file.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "core/error.h"

namespace lucent {

AtomicFile::AtomicFile(std::filesystem::path target) : target_(std::move(target)) {
    const std::string name = target_.string();
    // Only a regular file (or nothing) is replaced: renaming over a symbolic link,
    // a device or a FIFO would turn it into a regular file.
    std::error_code error;
    const auto status = std::filesystem::symlink_status(target_, error);
    if (std::filesystem::is_directory(status)) throw Error(name, "cannot write: is a directory");
    if (std::filesystem::exists(status) && !std::filesystem::is_regular_file(status))
        throw Error(name, std::string("cannot write: is ") +
                              (std::filesystem::is_symlink(status) ? "a symbolic link" : "not a regular file") +
                              " (Lucent replaces only regular files)");
    temporary_ = target_;
    temporary_ += ".tmp" + std::to_string(::getpid());
    stream_.open(temporary_, std::ios::binary | std::ios::trunc);
    if (!stream_) throw Error(name, std::string("cannot write: ") + std::strerror(errno));
}

AtomicFile::~AtomicFile() {
    if (committed_) return;
    stream_.close();
    std::error_code ignored;
    std::filesystem::remove(temporary_, ignored);
}

std::ofstream& AtomicFile::stream() { return stream_; }

void AtomicFile::commit() {
    stream_.flush();
    const bool ok = bool(stream_);
    stream_.close();
    if (!ok) throw Error(target_.string(), "cannot write: the write failed (disk full?)");
    std::error_code error;
    std::filesystem::rename(temporary_, target_, error);
    if (error) throw Error(target_.string(), "cannot write: " + error.message());
    committed_ = true;
}

void checkWritable(const std::filesystem::path& target) { AtomicFile probe(target); }

}  // namespace lucent
