#pragma once
// Every file Lucent reads is checked here before it is opened: it must be a
// regular file (a FIFO would block, /dev/zero never ends, a directory is no
// file), and what it asks Lucent to allocate must fit the memory budget. Output
// paths are checked against the inputs by file identity, never by name, so that
// no output replaces an input. The limits are listed in docs/robustness.md.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace lucent {

// The most one input may make Lucent allocate at once: a dense density grid, a
// mesh, a sample file. A larger claim is refused before any allocation.
inline constexpr uint64_t kMemoryBudgetBytes = uint64_t(4) << 30;  // 4 GiB
// Scene files and viewer scripts are text a person writes.
inline constexpr uint64_t kMaxTextFileBytes = uint64_t(64) << 20;  // 64 MiB

// The size of file, after checking that it exists and is a regular file (symbolic
// links are followed) of at most maxBytes; Error("FILE: WHAT ...") otherwise.
uint64_t regularFileSize(const std::filesystem::path& file, const std::string& what,
                         uint64_t maxBytes = kMemoryBudgetBytes);

// The whole of a regular text file of at most maxBytes.
std::string readTextFile(const std::filesystem::path& file, const std::string& what,
                         uint64_t maxBytes = kMaxTextFileBytes);

// Error naming file unless bytes fits the memory budget.
void checkMemoryBudget(uint64_t bytes, const std::filesystem::path& file, const std::string& what);

// Refuses to write output where it would replace one of inputs (the same file,
// through any name, link or hard link) or where it is not a regular file (a
// symbolic link, a device, a FIFO: replacing it would change what it is).
void checkOutputIsNoInput(const std::filesystem::path& output, const std::vector<std::filesystem::path>& inputs);

// Refuses two outputs that are the same file (the same path through any name).
void checkOutputsDistinct(const std::vector<std::filesystem::path>& outputs);

}  // namespace lucent
