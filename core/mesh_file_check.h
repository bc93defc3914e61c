#pragma once
// What a mesh file claims, checked before OpenMesh reads it: the vertex and face
// counts of a PLY or OFF header against the file's size (a 300-byte PLY may not
// claim 10^12 vertices) and the memory budget, and an OBJ's face indices against
// its vertex count (OpenMesh reports an out-of-range index as a bad vertex).
#include <cstdint>
#include <filesystem>

namespace lucent {

// The most vertices or faces one mesh may hold (OpenMesh keeps about 100 bytes
// per element; docs/robustness.md).
inline constexpr uint64_t kMaxMeshElements = uint64_t(1) << 26;

// Throws Error("FILE: problem") for a claim the file cannot hold. extension is
// lower-case with its dot (".ply", ".off", ".obj", ".stl"); size the file's bytes.
void checkMeshFileClaims(const std::filesystem::path& file, const std::string& extension, uint64_t size);

}  // namespace lucent
