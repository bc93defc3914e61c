#include "core/vdb_output.h"

#include <openvdb/io/Stream.h>
#include <openvdb/openvdb.h>

#include "core/atomic_file.h"
#include "core/error.h"

namespace lucent {

void writeVdbGrid(const std::filesystem::path& file, const std::string& gridName, const std::array<int, 3>& cells,
                  const Vec3& origin, const Vec3& edges, const std::vector<float>& values) {
    if (values.size() != size_t(cells[0]) * cells[1] * cells[2])
        throw Error(file.string(), "internal: the grid's values do not match its cells");
    openvdb::initialize();
    openvdb::FloatGrid::Ptr grid = openvdb::FloatGrid::create(0.0f);
    grid->setName(gridName);
    grid->setGridClass(openvdb::GRID_FOG_VOLUME);
    // Voxel (i, j, k) is centred at origin + edges (i + 1/2, j + 1/2, k + 1/2):
    // index space scaled by the cell edges (boxes of any aspect), then moved.
    openvdb::math::Mat4d m = openvdb::math::Mat4d::identity();
    m.preScale(openvdb::Vec3d(edges.x, edges.y, edges.z));
    m.postTranslate(openvdb::Vec3d(origin.x + 0.5 * edges.x, origin.y + 0.5 * edges.y, origin.z + 0.5 * edges.z));
    grid->setTransform(openvdb::math::Transform::createLinearTransform(m));
    openvdb::FloatGrid::Accessor access = grid->getAccessor();
    for (int k = 0; k < cells[2]; ++k)
        for (int j = 0; j < cells[1]; ++j)
            for (int i = 0; i < cells[0]; ++i) {
                const float v = values[i + size_t(cells[0]) * (j + size_t(cells[1]) * k)];
                if (v != 0.0f) access.setValue(openvdb::Coord(i, j, k), v);
            }
    AtomicFile out(file);
    try {
        openvdb::io::Stream(out.stream()).write(openvdb::GridCPtrVec{grid});
    } catch (const std::exception& e) {
        throw Error(file.string(), std::string("cannot write OpenVDB grid: ") + e.what());
    }
    out.commit();
}

}  // namespace lucent
