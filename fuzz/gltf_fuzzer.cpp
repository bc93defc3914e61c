// libFuzzer target: any bytes as a glTF file. The first byte picks the form
// (.glb or .gltf); the rest is the file, written in a folder of its own, so
// that the whole importer runs: Lucent's checks of the container and its URIs,
// tinygltf, then the accessors, nodes, materials and each object's mesh.
// Refusing with lucent::Error is fine; anything else is a bug.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/gltf_scene.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (size < 1) return 0;
    const std::filesystem::path folder =
        std::filesystem::temp_directory_path() / ("lucent-fuzz-gltf-" + std::to_string(::getpid()));
    std::filesystem::create_directories(folder);
    const std::filesystem::path file = folder / (data[0] % 2 ? "model.glb" : "model.gltf");
    std::ofstream(file, std::ios::binary).write(reinterpret_cast<const char*>(data + 1), std::streamsize(size - 1));
    try {
        const lucent::SceneDesc scene = lucent::importGltfScene(file);
        std::vector<std::string> warnings;
        for (const auto& object : scene.objects) lucent::loadGltfMesh(object.mesh, object.gltfNode, warnings);
    } catch (const lucent::Error&) {
    }
    std::filesystem::remove_all(folder);
    return 0;
}
