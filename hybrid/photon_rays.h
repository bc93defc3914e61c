#pragma once
// The ray map of each light (thesis 4.4.1): rays aimed at the object's grid on a
// jittered stratified pattern, each carrying its share of the light's power,
// started where they enter the grid (the grid has empty voxels around the object,
// so they start just outside the surface).
#include <cstdint>
#include <vector>

#include "core/scene.h"
#include "hybrid/internal/cl_layout.h"
#include "hybrid/voxelisation.h"

namespace lucent::hybrid {

struct RayMap {
    std::vector<clshared::PhotonRay> rays;
    Rgb emitted{0.0};  // the power the rays carry into the grid, W
};

// About `count` rays per light. A point light sends them uniformly over the cone
// that holds the grid's bounding sphere (I * solid angle / N each); a sphere
// light four times as many, in four strata of its disk; a directional light
// over the square that holds the sphere's shadow (E * area / N each).
RayMap rayMapFor(const std::vector<Light>& lights, const GridShape& grid, int count, uint64_t seed);

}  // namespace lucent::hybrid
