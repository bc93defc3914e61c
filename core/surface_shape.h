#pragma once
// What a closed mesh's surface is like, where that decides how well the fast
// methods see through a refracting boundary: ss draws each sample where one
// pixel's refracted ray passes nearest, and lbl's view bends through a smoothed
// index. Both hold when the refracted view rays cross nowhere inside. A smooth
// convex body of index below 2 is such a boundary (a ball lens focuses beyond
// its far side, at n / (2 (n - 1)) radii from its centre). Flat faces joined by
// tight bends, creases and concave parts fold the view: a sample is seen
// through two faces, or through one part and another, and the fast methods
// draw it once (docs/accuracy.md, ss through a refracting boundary).
#include "core/triangle_mesh.h"

namespace lucent {

struct SurfaceShape {
    bool convex = true;             // every edge bends outwards (within a 1e-4 of the box's diagonal)
    double sharpestDegrees = 0.0;   // the largest angle between the normals of two faces that share an edge
    double largestFlatShare = 0.0;  // the largest coplanar patch's share of the surface's area
};
SurfaceShape surfaceShape(const TriangleMesh& mesh);

// Normals of faces sharing an edge that agree within this angle lie in one flat patch.
inline constexpr double kCoplanarDegrees = 0.05;
// A flat patch above this share of the area is a face, not a facet of a
// tessellated curve: the measured smooth bodies (a sphere, an ellipsoid, a
// capsule) have patches below 0.5% of their area, the boxes' faces 10-35%.
inline constexpr double kLargestFacetShare = 0.02;

// Convex, no crease (kCreaseDegrees, the shading normals' own) and no flat face.
bool smoothConvex(const SurfaceShape& shape);

}  // namespace lucent
