#pragma once
// How a sample set becomes what the sample programs read: the storage-buffer
// records of gpu_layout.h and, for objects of constant-density slabs, the slab
// table scatter.frag integrates through. Pure CPU work, tested without GL.
#include <vector>

#include <glm/glm.hpp>

#include "core/sample_set.h"
#include "runtime/internal/gpu_layout.h"

namespace lucent {

std::vector<gpu::Sample> packSamples(const SampleSet& samples);

// Every sample has the same sigma_t: the attenuation towards the camera is exp(-sigma_t distance).
bool isHomogeneous(const SampleSet& samples);

// Whether the scattering fragments attenuate from each pixel's front face
// (scatter.vert, VIEW_FROM_FRONT): the Lucent scheme, with sigma_t constant or
// constant in the slabs scatter.frag integrates through.
bool attenuatesFromFront(const SampleSet& samples);

// The density slabs along parameters.regionAxis when sigma_t is constant in each:
// per slab [lo, hi, 0, 0] and [sigma_t rgb, 0], sorted by [lo, hi]. Empty for a
// homogeneous set, a set without slabs, a density that varies inside a slab, or
// more than kMaxSlabs slabs (the size of scatter.frag's table).
struct SlabTable {
    static constexpr size_t kMaxSlabs = 16;
    std::vector<glm::vec4> bounds, extinction;
    bool empty() const { return bounds.empty(); }
};
SlabTable findSlabs(const SampleSet& samples);

}  // namespace lucent
