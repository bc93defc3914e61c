#version 450 core
// Every depth layer segment.frag reads, in one pass over the meshes instead of
// one pass each (FrameTargets::Layers::OnePass): the two nearest front faces,
// the two nearest back faces and the farthest back face of each pixel, kept in
// the layers of an R32UI array by atomic minima and maxima on the depth's bits
// (a non-negative float orders as its bits do). The k nearest of a stream by
// atomic minima: the first slot keeps the least, and whatever it held before, or
// the new depth if larger, goes on to the next slot (exact in any order of
// arrival). A depth the first slot already holds is a coincident face: kept
// once, as depth peeling keeps it (peel.frag's strict test). On llvmpipe each
// mesh pass costs its vertex work on the application's thread, whatever few
// fragments it has.
#include "gpu_layout.h"

layout(r32ui, binding = 0) uniform coherent uimage2DArray layers;  // fronts, backs, farthest back

void keepNearest(ivec2 pixel, int first, uint depth) {
    for (int k = 0; k < kMaxRaySegments; ++k) {
        uint held = imageAtomicMin(layers, ivec3(pixel, first + k), depth);
        if (held == depth) return;
        depth = max(held, depth);
    }
}

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    uint depth = floatBitsToUint(gl_FragCoord.z);
    if (gl_FrontFacing) {
        keepNearest(pixel, 0, depth);
    } else {
        keepNearest(pixel, kMaxRaySegments, depth);
        imageAtomicMax(layers, ivec3(pixel, 2 * kMaxRaySegments), depth);
    }
}
