#pragma once
// Init pass of the hybrid (thesis 4.3): an object as a grid of cubic voxels.
// Each voxel holds sigma_t premultiplied by the share of it the medium occupies
// (from 2x2x2 = 8 sub-samples per voxel), that share, and the refractive index
// with its gradient, smoothed so that rays bend smoothly across the boundary.
#include <array>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "core/grid_index.h"
#include "core/math.h"
#include "core/volume_object.h"

namespace lucent::hybrid {

// The lattice works on blocks of kBlock^3 voxels (thesis 4.5): every dimension is a multiple.
inline constexpr int kBlock = 4;

struct GridShape {
    Vec3 origin{0.0};  // corner of voxel (0, 0, 0)
    double voxel = 1;  // edge length
    std::array<int, 3> dims{0, 0, 0};

    size_t count() const { return index().count(); }
    GridIndex index() const { return {dims}; }
    // The centre of voxel (i, j, k), world units.
    Vec3 centre(int i, int j, int k) const { return origin + voxel * Vec3(i + 0.5, j + 0.5, k + 0.5); }
    Bounds3 bounds() const { return {origin, origin + voxel * Vec3(dims[0], dims[1], dims[2])}; }
    // "a 64x48x40 grid for object 'NAME'", for messages.
    std::string describe(const std::string& object) const {
        return "a " + std::to_string(dims[0]) + "x" + std::to_string(dims[1]) + "x" + std::to_string(dims[2]) +
               " grid for object '" + object + "'";
    }
};

// Cubic voxels, `resolution` of them along the longest side of the object's box
// with one empty voxel on each side, every dimension rounded up to kBlock.
GridShape gridShapeFor(const Bounds3& objectBounds, int resolution);

// What voxels hold besides medium: empty ones let light leave, opaque ones (a
// blocker fills most of the voxel) absorb it.
inline constexpr float kOpaque = -1.0f;

struct Voxelisation {
    GridShape shape;
    std::vector<glm::vec4> material;    // rgb: sigma_t * occupancy; a: occupancy in [0, 1], or kOpaque
    std::vector<glm::vec4> refraction;  // x: index n; yzw: grad n per world unit
    bool refracting = false;            // n differs from 1 somewhere
    double ior = 1.0;                   // the medium's index, inside

    // The index and its gradient as ScatteringGrid::refraction holds them (four
    // floats per voxel), empty when nothing refracts: what the view pass bends along.
    std::vector<float> viewRefraction() const;
};

Voxelisation voxelise(const VolumeObject& object, int resolution);

// A Gaussian blur of standard deviation sigmaVoxels along each axis (separable), edges clamped.
void gaussianBlur(std::vector<float>& values, const std::array<int, 3>& dims, double sigmaVoxels);

}  // namespace lucent::hybrid
