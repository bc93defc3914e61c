#pragma once
// A 64-bit FNV-1a digest of files and text: cheap identity for "was this sample
// file made from this mesh and medium?" and the sample file's checksum.
#include <cstdint>
#include <filesystem>
#include <string_view>

namespace lucent {

class Fingerprint {
public:
    void addBytes(const void* data, size_t size) {
        const auto* p = static_cast<const unsigned char*>(data);
        for (size_t i = 0; i < size; ++i) hash_ = (hash_ ^ p[i]) * 0x100000001b3ull;
    }
    void addText(std::string_view text) { addBytes(text.data(), text.size()); }
    // A missing, irregular or oversized file adds only its name; loading it later reports the problem.
    void addFile(const std::filesystem::path& file);
    uint64_t value() const { return hash_; }

private:
    uint64_t hash_ = 0xcbf29ce484222325ull;
};

}  // namespace lucent
