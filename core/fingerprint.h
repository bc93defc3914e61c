#pragma once
// A 64-bit XXH3 digest (xxHash, seed 0) of files and text: cheap identity for
// "was this sample file made from this mesh and medium?" and the sample file's
// checksum. Adding bytes in pieces gives the digest of their concatenation.
// (XXH3 reads at memory speed; FNV-1a, one multiply per byte, was most of a
// sample file's load.)
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string_view>

struct XXH3_state_s;

namespace lucent {

class Fingerprint {
public:
    Fingerprint();
    ~Fingerprint();
    Fingerprint(const Fingerprint&) = delete;
    Fingerprint& operator=(const Fingerprint&) = delete;

    void addBytes(const void* data, size_t size);
    void addText(std::string_view text) { addBytes(text.data(), text.size()); }
    // A missing, irregular or oversized file adds only its name; loading it later reports the problem.
    void addFile(const std::filesystem::path& file);
    uint64_t value() const;

private:
    struct FreeState {
        void operator()(XXH3_state_s* state) const;
    };
    std::unique_ptr<XXH3_state_s, FreeState> state_;
};

}  // namespace lucent
