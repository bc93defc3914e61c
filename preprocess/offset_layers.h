#pragma once
// Offset layers (thesis 3.2.2): concentric inner surfaces at given depths under
// the boundary, extracted by marching cubes from the mesh's signed distance field.
// OpenVDB builds the narrow-band distance field and meshes its iso-surfaces;
// docs/preprocess.md records why it was chosen over CGAL's Mesh_3 route.
#include <array>
#include <cstdint>
#include <vector>

#include "core/triangle_mesh.h"

namespace lucent {

struct OffsetLayer {
    double depth;  // distance under the boundary
    TriangleMesh surface;
};

// One layer per depth (depths ascending); a depth deeper than the object's
// thickest point yields no layer, so the result may hold fewer entries.
std::vector<OffsetLayer> buildOffsetLayers(const TriangleMesh& boundary, const std::vector<double>& depths,
                                           double voxelSize);

}  // namespace lucent
