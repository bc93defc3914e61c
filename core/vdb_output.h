#pragma once
// A regular grid of float values written as an OpenVDB file (one FloatGrid),
// for tools that read volumes (Houdini, Blender, OpenVDB's own viewers): what
// `lucent transport --vdb` gives of the whole solution.
#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "core/math.h"

namespace lucent {

// values[i + nx (j + ny k)] at the centre of cell (i, j, k) of the box from
// origin with cells of size edges; zero values stay inactive (the background).
// Written whole or not at all (core/atomic_file.h). Throws Error naming file.
void writeVdbGrid(const std::filesystem::path& file, const std::string& gridName, const std::array<int, 3>& cells,
                  const Vec3& origin, const Vec3& edges, const std::vector<float>& values);

}  // namespace lucent
