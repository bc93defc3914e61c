// libFuzzer target: any bytes as a mesh file. The first byte picks the format
// (OBJ, PLY, OFF or STL); the rest is the file, written where loadClosedMesh reads
// it, so that the whole reader runs: Lucent's checks of what the file claims,
// then OpenMesh. Refusing with lucent::Error is fine; anything else is a bug.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/triangle_mesh.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (size < 1) return 0;
    static const char* const kExtensions[] = {".obj", ".ply", ".off", ".stl"};
    const std::filesystem::path file = std::filesystem::temp_directory_path() /
                                       ("lucent-fuzz-mesh-" + std::to_string(::getpid()) + kExtensions[data[0] % 4]);
    std::ofstream(file, std::ios::binary).write(reinterpret_cast<const char*>(data + 1), std::streamsize(size - 1));
    try {
        std::vector<std::string> warnings;
        lucent::loadClosedMesh(file, warnings);
    } catch (const lucent::Error&) {
    }
    std::filesystem::remove(file);
    return 0;
}
