#include "preprocess/openvdb/vdb_distance_field.h"

#include <openvdb/tools/MeshToVolume.h>
#include <openvdb/tools/VolumeToMesh.h>

#include <cmath>

namespace lucent {

VdbDistanceField::VdbDistanceField(const TriangleMesh& boundary, double voxelSize, double deepest)
    : DistanceField(boundary, voxelSize) {
    openvdb::initialize();
    std::vector<openvdb::Vec3s> points;
    points.reserve(boundary.positions.size());
    for (const Vec3& p : boundary.positions) {
        const Vec3 q = toGrid(p);
        points.emplace_back(float(q.x), float(q.y), float(q.z));
    }
    std::vector<openvdb::Vec3I> triangles;
    triangles.reserve(boundary.triangles.size());
    for (const auto& t : boundary.triangles) triangles.emplace_back(t[0], t[1], t[2]);
    const std::vector<openvdb::Vec4I> noQuads;
    // The interior band reaches a few voxels past the deepest layer, so that marching
    // cubes sees the sign change there and central differences have neighbours.
    const float interiorBand = float(std::ceil(deepest / voxelSize) + 3.0);
    const auto transform = openvdb::math::Transform::createLinearTransform(voxelSize / scale());
    grid_ = openvdb::tools::meshToSignedDistanceField<openvdb::FloatGrid>(*transform, points, triangles, noQuads, 3.0f,
                                                                          interiorBand);
}

std::vector<OffsetLayer> VdbDistanceField::offsetLayers(const std::vector<double>& depths) const {
    std::vector<OffsetLayer> layers;
    for (double depth : depths) {
        std::vector<openvdb::Vec3s> vertices;
        std::vector<openvdb::Vec3I> tris;
        std::vector<openvdb::Vec4I> quads;
        openvdb::tools::volumeToMesh(*grid_, vertices, tris, quads, -depth / scale(), 0.0);  // inside is negative
        if (vertices.empty()) break;
        OffsetLayer layer;
        layer.depth = depth;
        layer.surface.positions.reserve(vertices.size());
        for (const auto& v : vertices) layer.surface.positions.push_back(toWorld(Vec3(v.x(), v.y(), v.z())));
        auto& out = layer.surface.triangles;
        out.reserve(tris.size() + 2 * quads.size());
        for (const auto& t : tris) out.push_back({t.x(), t.y(), t.z()});
        for (const auto& q : quads) {
            out.push_back({q[0], q[1], q[2]});
            out.push_back({q[0], q[2], q[3]});
        }
        layers.push_back(std::move(layer));
    }
    return layers;
}

}  // namespace lucent
