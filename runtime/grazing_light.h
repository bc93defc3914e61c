#pragma once
// How much light falls on what the camera sees of an optically thick object.
// Its closed form (runtime/internal/optically_thick.frag) lights each point
// through the face it lies on: light that enters a face the camera does not
// see and leaves through one it sees, within a few mean free paths of the edge
// or terminator between them, is left out. That matters only where little of
// the seen surface is lit (lucent-bench-grazing, docs/results/grazing.md: a cube
// and a sphere at sigma_t 80 lit from in front to behind).
#include <string>
#include <vector>

#include "core/scene.h"
#include "core/triangle_mesh.h"

namespace lucent {

// Below this lighting of the seen surface the closed form misses the reference by
// 10% or more: 5.2% at 0.026 and 15.5% at 0.009 on the cube, 6.9% at 0.025 and
// 10.0% at 0.013 on the sphere; black against thin bright edges at 0 (docs/results/grazing.md).
inline constexpr double kGrazingLight = 0.03;

// The mean over the surface the camera at eye sees (faces turned to it, each
// weighted by the solid angle it covers; occlusion not counted) of the cosine
// of the light's incidence times a spot's falloff: 1 where every seen face is
// lit head-on, 0 where none is lit. The largest over the lights with any power.
double seenSurfaceLighting(const TriangleMesh& worldMesh, const Vec3& eye, const std::vector<Light>& lights);

// Empty when seenSurfaceLighting reaches kGrazingLight; otherwise one line for
// limitations(), naming the object and the lighting.
std::string grazingLightLimitation(const std::string& object, double lighting);

}  // namespace lucent
