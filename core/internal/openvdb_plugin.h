#pragma once
// What core reads and writes with OpenVDB, in the plug-in liblucent_core_openvdb
// (core/openvdb/, core/plugin_library.h): OpenVDB's types stay inside it.
#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "core/math.h"

namespace lucent {

struct DenseFloatGrid {
    std::array<int, 3> nodes{};  // x fastest
    Bounds3 bounds;              // from the first node to the last
    std::vector<float> values;
};

struct CoreOpenVdbPlugin {
    // A float grid of a .vdb file, densified over its active voxels' box; every
    // value finite and not negative. Throws Error naming the file.
    DenseFloatGrid (*readFloatGrid)(const std::filesystem::path& file, const std::string& gridName);
    // core/vdb_output.h's writeVdbGrid, its arguments checked.
    void (*writeFloatGrid)(const std::filesystem::path& file, const std::string& gridName,
                           const std::array<int, 3>& cells, const Vec3& origin, const Vec3& edges,
                           const std::vector<float>& values);
};

// Opens the plug-in on first use.
const CoreOpenVdbPlugin& coreOpenVdbPlugin();

}  // namespace lucent
