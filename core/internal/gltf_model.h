#pragma once
// A glTF 2.0 file (.gltf with its buffers, or .glb) read through tinygltf with
// every access checked as Lucent checks its other inputs (docs/robustness.md):
// the file and each buffer regular and within the memory budget, buffer URIs
// relative and inside the model's folder, no shell expansion of paths (tinygltf's
// default expands them with wordexp), images never decoded (Lucent maps no
// texture), and every accessor inside its buffer before a byte is copied.
#include <tiny_gltf.h>

#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "core/math.h"

namespace lucent::gltf {

// Error("FILE: problem") for anything malformed or unsafe; tinygltf's warnings are appended.
tinygltf::Model readModel(const std::filesystem::path& file, std::vector<std::string>& warnings);

// A node of the model's scene with its matrix from node space to the scene's.
struct PlacedNode {
    int node = -1;
    glm::dmat4 world{1.0};
};

// Every node of the default scene (the first without one; every root node
// without scenes), depth first, parents before children. Error when a node is
// reached twice (glTF's nodes form a forest) or a transform is not finite.
std::vector<PlacedNode> placedNodes(const tinygltf::Model& model, const std::string& file);

// The triangles of one mesh, every primitive joined (triangle lists, strips
// and fans; points and lines are left out with a warning), positions in the
// mesh's own space. Error for an accessor outside its buffer or of a wrong type.
struct RawTriangles {
    std::vector<Vec3> positions;
    std::vector<std::array<uint32_t, 3>> triangles;
};
RawTriangles meshTriangles(const tinygltf::Model& model, int mesh, const std::string& file,
                           std::vector<std::string>& warnings);

// Merges the vertices within tolerance of each other (exporters split a vertex
// wherever its normal or UV differs, which opens every seam) and drops the
// triangles that collapse. Keeps the first vertex of each cluster.
RawTriangles weldVertices(const RawTriangles& mesh, double tolerance);

}  // namespace lucent::gltf
