#pragma once
// What a volumetric multiple-scattering method hands the runtime for one object
// (hybrid/ makes it, runtime/ draws it, neither sees the other): a box of cubic
// voxels holding, per colour channel, the light the medium scatters towards any
// direction per unit length of a view ray, and the extinction that dims it on
// the way to the eye. The view pass integrates
//   L = int exp(-int sigma_t) source dt      (thesis 4.6.2)
// along each pixel's ray inside the object (bent by the index, when it refracts).
#include <array>
#include <vector>

#include "core/grid_index.h"
#include "core/math.h"

namespace lucent {

struct ScatteringGrid {
    Bounds3 bounds;  // the box the voxels tile, world units
    std::array<int, 3> dims{0, 0, 0};
    std::vector<float> source;      // rgb per voxel, x fastest: sigma_s phi / (4 pi), W / (m^3 sr) in scene units
    std::vector<float> extinction;  // rgb per voxel: sigma_t weighted by the voxel's occupancy
    // Per voxel the refractive index n and its gradient (per world unit), four
    // floats, smoothed across the boundary; empty when the medium is
    // index-matched. View rays then bend along the eikonal equation (thesis 4.3).
    std::vector<float> refraction;
    double ior = 1.0;  // the medium's own index inside (refraction's, before smoothing)

    size_t voxelCount() const { return index().count(); }
    GridIndex index() const { return {dims}; }
};

}  // namespace lucent
