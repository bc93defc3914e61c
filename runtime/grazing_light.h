#pragma once
// How much light falls on what the camera sees of an optically thick object.
// ss marches each pixel's ray with the light's way through the medium read from
// maps of the mesh seen from the light (runtime/internal/optically_thick.frag).
// Where the seen surface is lit at grazing incidence, the lit sliver spans less
// than a texel of those maps seen from the light, and the light there is off
// (lucent-bench-grazing, docs/results/grazing.md: a cube and a sphere at sigma_t
// 80 lit from in front to behind). Lit from beside or behind, the seen surface
// unlit, the light across the edges is drawn.
#include <string>
#include <vector>

#include "core/scene.h"
#include "core/triangle_mesh.h"

namespace lucent {

// Below this lighting of the seen surface, and above none, ss may miss the
// reference by 10% or more: 58% at 0.009 on the cube (8.1% at 0.026), 57% at
// 0.002 on the sphere (5.3% at 0.013); with none of it lit, 0.1% to 9.3% on
// the cube (docs/results/grazing.md).
inline constexpr double kGrazingLight = 0.02;

// The mean over the surface the camera at eye sees (faces turned to it, each
// weighted by the solid angle it covers; occlusion not counted) of the cosine
// of the light's incidence times a spot's falloff: 1 where every seen face is
// lit head-on, 0 where none is lit. The largest over the lights with any power.
double seenSurfaceLighting(const TriangleMesh& worldMesh, const Vec3& eye, const std::vector<Light>& lights);

// Empty when seenSurfaceLighting reaches kGrazingLight or is 0; otherwise one
// line for limitations(), naming the object and the lighting.
std::string grazingLightLimitation(const std::string& object, double lighting);

}  // namespace lucent
