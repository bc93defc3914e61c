// libFuzzer target: any bytes as a density grid. The first byte picks raw or
// OpenVDB; for raw, the next three bytes are the dims (1 to 16 each); the rest is
// the file, loaded as the scene would load it. Refusing with lucent::Error is
// fine; anything else is a bug.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "core/density_field.h"
#include "core/error.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (size < 4) return 0;
    const bool vdb = data[0] & 1;
    const std::filesystem::path file = std::filesystem::temp_directory_path() /
                                       ("lucent-fuzz-grid-" + std::to_string(::getpid()) + (vdb ? ".vdb" : ".raw"));
    std::ofstream(file, std::ios::binary).write(reinterpret_cast<const char*>(data + 4), std::streamsize(size - 4));
    try {
        if (vdb) {
            lucent::loadVdbGrid(file, "density");
        } else {
            lucent::Bounds3 bounds;
            bounds.extend(lucent::Vec3(-1.0));
            bounds.extend(lucent::Vec3(1.0));
            lucent::loadRawGrid(file, 1 + data[1] % 16, 1 + data[2] % 16, 1 + data[3] % 16, bounds);
        }
    } catch (const lucent::Error&) {
    }
    std::filesystem::remove(file);
    return 0;
}
