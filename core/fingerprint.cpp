#include "core/fingerprint.h"

#include <fstream>
#include <vector>

namespace lucent {

void Fingerprint::addFile(const std::filesystem::path& file) {
    addText(file.filename().string());
    std::ifstream in(file, std::ios::binary);
    std::vector<char> buffer(1 << 16);
    while (in) {
        in.read(buffer.data(), std::streamsize(buffer.size()));
        addBytes(buffer.data(), size_t(in.gcount()));
    }
}

}  // namespace lucent
