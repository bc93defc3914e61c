#include "core/surface_shape.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <unordered_map>

namespace lucent {
namespace {

// The two faces on each edge (a closed mesh has exactly two).
std::vector<std::array<uint32_t, 2>> edgeFaces(const TriangleMesh& mesh) {
    std::unordered_map<uint64_t, uint32_t> firstFace;
    std::vector<std::array<uint32_t, 2>> pairs;
    firstFace.reserve(3 * mesh.triangles.size() / 2);
    for (uint32_t f = 0; f < mesh.triangles.size(); ++f)
        for (int c = 0; c < 3; ++c) {
            const uint32_t a = mesh.triangles[f][c], b = mesh.triangles[f][(c + 1) % 3];
            const uint64_t key = (uint64_t(std::min(a, b)) << 32) | std::max(a, b);
            const auto [it, first] = firstFace.emplace(key, f);
            if (!first) pairs.push_back({it->second, f});
        }
    return pairs;
}

uint32_t oppositeCorner(const TriangleMesh& mesh, uint32_t face, uint32_t other) {
    for (uint32_t v : mesh.triangles[face])
        if (std::find(mesh.triangles[other].begin(), mesh.triangles[other].end(), v) == mesh.triangles[other].end())
            return v;
    return mesh.triangles[face][0];  // the same three corners: a degenerate pair, flat
}

uint32_t root(std::vector<uint32_t>& parent, uint32_t f) {
    while (parent[f] != f) f = parent[f] = parent[parent[f]];
    return f;
}

}  // namespace

SurfaceShape surfaceShape(const TriangleMesh& mesh) {
    SurfaceShape shape;
    const size_t faces = mesh.triangles.size();
    std::vector<Vec3> unit(faces);
    for (size_t f = 0; f < faces; ++f) {
        const Vec3 n = mesh.faceNormal(f);
        const double length = glm::length(n);
        unit[f] = length > 0.0 ? n / length : Vec3(0.0);
    }
    const Bounds3 box = mesh.bounds();
    const double tolerance = 1e-4 * glm::length(box.max - box.min);
    const double cosCoplanar = std::cos(kCoplanarDegrees * kPi / 180.0);
    std::vector<uint32_t> parent(faces);
    std::iota(parent.begin(), parent.end(), 0u);
    for (const auto& [f, g] : edgeFaces(mesh)) {
        const double cosine = std::clamp(glm::dot(unit[f], unit[g]), -1.0, 1.0);
        shape.sharpestDegrees = std::max(shape.sharpestDegrees, std::acos(cosine) * 180.0 / kPi);
        // g's far corner lies on the inner side of f's plane where the edge bends outwards.
        const Vec3 corner = mesh.positions[oppositeCorner(mesh, g, f)];
        if (glm::dot(unit[f], corner - mesh.positions[mesh.triangles[f][0]]) > tolerance) shape.convex = false;
        if (cosine >= cosCoplanar) parent[root(parent, f)] = root(parent, g);
    }
    std::vector<double> patchArea(faces, 0.0);
    double total = 0.0;
    for (uint32_t f = 0; f < faces; ++f) {
        const double area = 0.5 * glm::length(mesh.faceNormal(f));
        patchArea[root(parent, f)] += area;
        total += area;
    }
    if (total > 0.0) shape.largestFlatShare = *std::max_element(patchArea.begin(), patchArea.end()) / total;
    return shape;
}

bool smoothConvex(const SurfaceShape& shape) {
    return shape.convex && shape.sharpestDegrees < kCreaseDegrees && shape.largestFlatShare <= kLargestFacetShare;
}

}  // namespace lucent
