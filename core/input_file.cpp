#include "core/input_file.h"

#include <sys/stat.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

#include "core/error.h"

namespace lucent {
namespace {

std::string describeType(mode_t mode) {
    if (S_ISDIR(mode)) return "a directory";
    if (S_ISFIFO(mode)) return "a FIFO";
    if (S_ISCHR(mode)) return "a character device";
    if (S_ISBLK(mode)) return "a block device";
    if (S_ISSOCK(mode)) return "a socket";
    if (S_ISLNK(mode)) return "a symbolic link";
    return "not a regular file";
}

std::string gib(uint64_t bytes) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g GiB", double(bytes) / double(uint64_t(1) << 30));
    return text;
}

std::string limitText(uint64_t bytes) {
    return bytes >= (uint64_t(1) << 30) ? gib(bytes) : std::to_string(bytes >> 20) + " MiB";
}

}  // namespace

uint64_t regularFileSize(const std::filesystem::path& file, const std::string& what, uint64_t maxBytes) {
    struct stat s {};
    if (::stat(file.c_str(), &s) != 0) throw Error(file.string(), "cannot open " + what + ": " + std::strerror(errno));
    if (!S_ISREG(s.st_mode))
        throw Error(file.string(),
                    "cannot read " + what + ": it is " + describeType(s.st_mode) + ", not a regular file");
    const uint64_t size = uint64_t(s.st_size);
    if (size > maxBytes)
        throw Error(file.string(), what + " of " + std::to_string(size) + " bytes is larger than the " +
                                       limitText(maxBytes) + " Lucent reads (docs/robustness.md)");
    return size;
}

std::string readTextFile(const std::filesystem::path& file, const std::string& what, uint64_t maxBytes) {
    regularFileSize(file, what, maxBytes);
    std::ifstream in(file, std::ios::binary);
    if (!in) throw Error(file.string(), "cannot open " + what + ": " + std::strerror(errno));
    std::stringstream text;
    text << in.rdbuf();
    if (in.bad()) throw Error(file.string(), "cannot read " + what);
    return text.str();
}

void checkMemoryBudget(uint64_t bytes, const std::filesystem::path& file, const std::string& what) {
    if (bytes > kMemoryBudgetBytes)
        throw Error(file.string(), what + " would need " + gib(bytes) + ", more than the memory budget of " +
                                       gib(kMemoryBudgetBytes) + " (docs/robustness.md)");
}

void checkOutputIsNoInput(const std::filesystem::path& output, const std::vector<std::filesystem::path>& inputs) {
    struct stat out {};
    if (::lstat(output.c_str(), &out) != 0) return;  // a new file can be no input
    if (!S_ISREG(out.st_mode))
        throw Error(output.string(),
                    "will not write over " + describeType(out.st_mode) + " (Lucent replaces only regular files)");
    for (const std::filesystem::path& input : inputs) {
        struct stat in {};
        if (::stat(input.c_str(), &in) == 0 && in.st_dev == out.st_dev && in.st_ino == out.st_ino)
            throw Error(output.string(), "will not write over an input of this run (it is " + input.string() + ")");
    }
}

void checkOutputsDistinct(const std::vector<std::filesystem::path>& outputs) {
    for (size_t i = 0; i < outputs.size(); ++i)
        for (size_t j = 0; j < i; ++j) {
            std::error_code e1, e2;
            const auto a = std::filesystem::weakly_canonical(outputs[i], e1);
            const auto b = std::filesystem::weakly_canonical(outputs[j], e2);
            if ((!e1 && !e2 && a == b) || std::filesystem::equivalent(outputs[i], outputs[j], e1))
                throw Error(outputs[i].string(), "is the output of two objects (" + outputs[j].string() +
                                                     "); give each object its own sample file");
        }
}

}  // namespace lucent
