#include "core/vdb_output.h"

#include "core/error.h"
#include "core/internal/openvdb_plugin.h"

namespace lucent {

void writeVdbGrid(const std::filesystem::path& file, const std::string& gridName, const std::array<int, 3>& cells,
                  const Vec3& origin, const Vec3& edges, const std::vector<float>& values) {
    if (values.size() != size_t(cells[0]) * cells[1] * cells[2])
        throw Error(file.string(), "internal: the grid's values do not match its cells");
    coreOpenVdbPlugin().writeFloatGrid(file, gridName, cells, origin, edges, values);
}

}  // namespace lucent
