#pragma once
// Maximal Poisson-disk sampling of triangle surfaces with radii that vary over
// the surface (thesis 3.2.4), by hierarchical dart throwing (White, Cline and
// Egbert): darts land in active triangle fragments chosen by area; a fragment
// that a disk covers entirely is dropped, any other is split in four and its
// children go one level down. When no fragment is left the set is maximal up to
// the finest level, and the work is linear in the number of fragments. Tiles of
// the surface far enough apart take their darts at once, on every core; the
// samples are the same for any thread count.
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/math.h"

namespace lucent {

struct RadiusSurface {
    std::vector<Vec3> positions;
    std::vector<double> radius;  // disk radius at each vertex, interpolated linearly over faces
    std::vector<std::array<uint32_t, 3>> triangles;
};

struct DiskSample {
    Vec3 position;
    double radius;
};

// No two samples p, q are closer than max(r_p, r_q); every point x of the surface
// lies within r_q of some sample q, up to fragments smaller than finestEdge.
// Stops early, with maxSamples samples, when that budget is reached (the caller
// says so: a set cut short is not maximal).
std::vector<DiskSample> poissonDiskSample(const RadiusSurface& surface, uint64_t seed, double finestEdge,
                                          size_t maxSamples = SIZE_MAX);

}  // namespace lucent
