#include "preprocess/offset_layers.h"

#include <openvdb/openvdb.h>
#include <openvdb/tools/MeshToVolume.h>
#include <openvdb/tools/VolumeToMesh.h>

#include <algorithm>
#include <cmath>

namespace lucent {

std::vector<OffsetLayer> buildOffsetLayers(const TriangleMesh& boundary, const std::vector<double>& depths,
                                           double voxelSize) {
    std::vector<OffsetLayer> layers;
    if (depths.empty()) return layers;
    openvdb::initialize();

    // Work relative to the bounding-box centre so that single-precision voxel
    // coordinates keep their accuracy for models far from the origin.
    const Vec3 centre = boundary.bounds().center();
    std::vector<openvdb::Vec3s> points;
    points.reserve(boundary.positions.size());
    for (const Vec3& p : boundary.positions) {
        const Vec3 q = p - centre;
        points.emplace_back(float(q.x), float(q.y), float(q.z));
    }
    std::vector<openvdb::Vec3I> triangles;
    triangles.reserve(boundary.triangles.size());
    for (const auto& t : boundary.triangles) triangles.emplace_back(t[0], t[1], t[2]);
    const std::vector<openvdb::Vec4I> noQuads;

    // The interior band must reach a little past the deepest layer for marching
    // cubes to see the sign change there.
    const double deepest = *std::max_element(depths.begin(), depths.end());
    const float interiorBand = float(std::ceil(deepest / voxelSize) + 3.0);
    const auto transform = openvdb::math::Transform::createLinearTransform(voxelSize);
    const auto sdf = openvdb::tools::meshToSignedDistanceField<openvdb::FloatGrid>(*transform, points, triangles,
                                                                                  noQuads, 3.0f, interiorBand);

    for (double depth : depths) {
        std::vector<openvdb::Vec3s> vertices;
        std::vector<openvdb::Vec3I> tris;
        std::vector<openvdb::Vec4I> quads;
        openvdb::tools::volumeToMesh(*sdf, vertices, tris, quads, -depth, 0.0);  // inside is negative
        if (vertices.empty()) break;
        OffsetLayer layer;
        layer.depth = depth;
        layer.surface.positions.reserve(vertices.size());
        for (const auto& v : vertices) layer.surface.positions.push_back(centre + Vec3(v.x(), v.y(), v.z()));
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
