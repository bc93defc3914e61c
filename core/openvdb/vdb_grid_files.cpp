// The plug-in liblucent_core_openvdb (core/internal/openvdb_plugin.h): reading
// and writing .vdb files, the only code of core that includes OpenVDB.
#include <openvdb/io/Stream.h>
#include <openvdb/openvdb.h>

#include <cmath>

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/input_file.h"
#include "core/internal/openvdb_plugin.h"
#include "core/isolated.h"

namespace lucent {
namespace {

DenseFloatGrid readFloatGrid(const std::filesystem::path& file, const std::string& gridName) {
    const std::string name = file.string();
    const uint64_t fileSize = regularFileSize(file, "OpenVDB file");
    openvdb::initialize();
    // OpenVDB asserts on some corrupt files (fuzz/grid_fuzzer.cpp): read it in a child first.
    const std::string death = deathInChild(
        [&] {
            openvdb::io::File vdb(name);
            vdb.open();
            vdb.readGrid(gridName);
        },
        5.0 + double(fileSize) / 2e6);
    if (!death.empty()) throw Error(name, "corrupt OpenVDB file (the OpenVDB reader died on it: " + death + ")");
    openvdb::FloatGrid::Ptr grid;
    try {
        openvdb::io::File vdb(name);
        vdb.open();
        openvdb::GridBase::Ptr base = vdb.readGrid(gridName);
        vdb.close();
        grid = openvdb::gridPtrCast<openvdb::FloatGrid>(base);
    } catch (const std::exception& e) {
        throw Error(name, std::string("cannot read OpenVDB grid '") + gridName + "': " + e.what());
    }
    if (!grid) throw Error(name, "grid '" + gridName + "' is not a float grid");
    if (!grid->transform().isLinear()) throw Error(name, "grid '" + gridName + "' has a non-linear transform");
    const openvdb::CoordBBox box = grid->evalActiveVoxelBoundingBox();
    if (box.empty()) throw Error(name, "grid '" + gridName + "' has no active voxels");
    const openvdb::Coord dim = box.dim();
    checkMemoryBudget(uint64_t(dim.x()) * uint64_t(dim.y()) * uint64_t(dim.z()) * sizeof(float), file,
                      "grid '" + gridName + "' densified over its active box of " + std::to_string(dim.x()) + "x" +
                          std::to_string(dim.y()) + "x" + std::to_string(dim.z()) + " voxels");
    DenseFloatGrid out;
    out.nodes = {dim.x(), dim.y(), dim.z()};
    out.values.resize(size_t(dim.x()) * dim.y() * dim.z());
    auto access = grid->getConstAccessor();
    size_t n = 0;
    for (int k = box.min().z(); k <= box.max().z(); ++k)
        for (int j = box.min().y(); j <= box.max().y(); ++j)
            for (int i = box.min().x(); i <= box.max().x(); ++i) {
                const float v = access.getValue(openvdb::Coord(i, j, k));
                if (!std::isfinite(v) || v < 0.0f)
                    throw Error(name, "grid '" + gridName + "' holds a negative or non-finite density");
                out.values[n++] = v;
            }
    const openvdb::Vec3d lo = grid->indexToWorld(box.min()), hi = grid->indexToWorld(box.max());
    out.bounds.extend(Vec3(lo.x(), lo.y(), lo.z()));
    out.bounds.extend(Vec3(hi.x(), hi.y(), hi.z()));
    return out;
}

void writeFloatGrid(const std::filesystem::path& file, const std::string& gridName, const std::array<int, 3>& cells,
                    const Vec3& origin, const Vec3& edges, const std::vector<float>& values) {
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

const CoreOpenVdbPlugin kTable{readFloatGrid, writeFloatGrid};

}  // namespace
}  // namespace lucent

extern "C" const void* lucentCoreOpenVdbPlugin() { return &lucent::kTable; }
