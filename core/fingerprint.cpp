#include "core/fingerprint.h"

#include <fstream>
#include <vector>

#include "core/error.h"
#include "core/input_file.h"

namespace lucent {

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
