// The structs and constants the OpenCL kernels and the host share, declared once
// (as runtime/internal/gpu_layout.h does for GLSL): the host includes this
// header; the kernels get it prepended by ClDevice::build. Only what OpenCL C
// and C++ both parse goes here.
#ifndef LUCENT_CL_LAYOUT_H
#define LUCENT_CL_LAYOUT_H

#ifdef __cplusplus
#include <CL/cl_platform.h>
namespace lucent::hybrid::clshared {
using float4 = cl_float4;
#define LUCENT_CL_CONSTANT(name, value) inline constexpr int name = value;
#else
#define LUCENT_CL_CONSTANT(name, value) constant int name = value;
#endif

// Edge of a lattice block in voxels (thesis 4.5: 4^3 voxels, 6 directions).
LUCENT_CL_CONSTANT(kBlockEdge, 4)
LUCENT_CL_CONSTANT(kBlockVoxels, 64)
LUCENT_CL_CONSTANT(kDirections, 6)  // +x -x +y -y +z -z: direction d ^ 1 is the opposite of d
// Fixed-point deposits (integer atomics): one unit is 2^-kFixedBits of a channel's emitted power.
LUCENT_CL_CONSTANT(kFixedBits, 40)

// A light ray of the photon marching pass (thesis 4.4).
typedef struct {
    float4 position;  // xyz: world position; w: 1 while the ray marches, 0 once it has left
    float4 velocity;  // xyz: n times the unit direction (thesis eq. 4.1-4.2); w: 1 once it has entered the medium
    float4 power;     // rgb: power the ray still carries, W
} PhotonRay;

#ifdef __cplusplus
static_assert(sizeof(PhotonRay) == 3 * sizeof(float4));
}  // namespace lucent::hybrid::clshared
#endif
#undef LUCENT_CL_CONSTANT

#endif
