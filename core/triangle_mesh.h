#pragma once
// A closed, consistently outward-oriented triangle mesh: the boundary of a
// translucent object or of an opaque blocker inside one.
#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "core/math.h"

namespace lucent {

struct TriangleMesh {
    std::vector<Vec3> positions;
    std::vector<std::array<uint32_t, 3>> triangles;

    Bounds3 bounds() const;
    double signedVolume() const;  // > 0 when faces point outwards
    double area() const;
    Vec3 faceNormal(size_t face) const;  // unnormalised, length = 2 * area
};

// The shading normals every method uses (the runtime's surface and skin passes,
// the reference and the path tracer): at each corner of each face, the
// area-weighted mean of the normals of the faces around that vertex that meet
// this face at less than kCreaseDegrees, so that smooth surfaces shade smoothly
// and a cube's edges stay sharp. Unit length; [face][corner].
constexpr double kCreaseDegrees = 45.0;
std::vector<std::array<Vec3, 3>> cornerNormals(const TriangleMesh& mesh);

// The corner normals interpolated at p (a point on the face) by its barycentric
// coordinates, as the rasteriser interpolates them, and normalised.
Vec3 interpolatedNormal(const TriangleMesh& mesh, const std::array<Vec3, 3>& corners, size_t face, const Vec3& p);

// Loads OBJ, PLY, OFF or STL through OpenMesh and checks that the mesh bounds a
// volume: non-empty, finite coordinates, every edge shared by exactly two faces,
// every vertex manifold. Inverted orientation is flipped; zero-area faces are
// dropped (they cannot be crossed) with a note appended to warnings.
// Throws Error("FILE: problem") otherwise.
TriangleMesh loadClosedMesh(const std::filesystem::path& path, std::vector<std::string>& warnings);

// The same checks for a mesh a host built in memory (single-precision vertices,
// as files give them); name stands for the file in errors and warnings.
TriangleMesh closedMesh(const std::vector<Vec3>& positions, const std::vector<std::array<uint32_t, 3>>& triangles,
                        const std::string& name, std::vector<std::string>& warnings);

}  // namespace lucent
