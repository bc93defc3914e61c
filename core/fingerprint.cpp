#include "core/fingerprint.h"

#include <xxhash.h>

#include <fstream>
#include <new>
#include <vector>

#include "core/error.h"
#include "core/input_file.h"

namespace lucent {

void Fingerprint::FreeState::operator()(XXH3_state_s* state) const { XXH3_freeState(state); }

Fingerprint::Fingerprint() : state_(XXH3_createState()) {
    if (!state_ || XXH3_64bits_reset(state_.get()) != XXH_OK) throw std::bad_alloc();
}

Fingerprint::~Fingerprint() = default;

void Fingerprint::addBytes(const void* data, size_t size) {
    if (size > 0) XXH3_64bits_update(state_.get(), data, size);
}

uint64_t Fingerprint::value() const { return XXH3_64bits_digest(state_.get()); }

void Fingerprint::addFile(const std::filesystem::path& file) {
    addText(file.filename().string());
    // Only regular files within the memory budget are hashed: a FIFO would block
    // here and a huge file take forever. Loading the file later says what is wrong.
    try {
        regularFileSize(file, "file");
    } catch (const Error&) {
        return;
    }
    std::ifstream in(file, std::ios::binary);
    std::vector<char> buffer(1 << 16);
    while (in) {
        in.read(buffer.data(), std::streamsize(buffer.size()));
        addBytes(buffer.data(), size_t(in.gcount()));
    }
}

}  // namespace lucent
