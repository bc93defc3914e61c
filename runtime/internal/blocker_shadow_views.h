#pragma once
// Where the blocker shadow maps look from (blocker_shadows.h): pure geometry,
// tested without GL.
#include <cstddef>
#include <vector>

#include <glm/glm.hpp>

#include "core/math.h"
#include "core/scene.h"
#include "core/similarity.h"

namespace lucent {

// Layers of the distance texture: six per light (one used by a directional light), at least six.
int blockerShadowLayers(size_t lightCount);

// Texels per side of each layer: 512 up to 4 lights, then fewer so that the
// maps stay within about 25 MB up to 256 lights; never fewer than 64.
int blockerShadowResolution(size_t lightCount);

// Texels per side of an optically thick object's entry maps (entry_distances.h),
// 24 bytes a texel: 512 for one light, then fewer so that they stay within
// about 38 MB (as one light's) up to the 256 lights a scene may have.
int entryMapResolution(size_t lightCount);

// The view-projection of each layer: around a point light the six 90-degree
// cube faces +x, -x, +y, -y, +z, -z (2 * axis + negative), each reaching past
// the blockers' bounding sphere; along a directional light one orthographic view
// enclosing that sphere. Unused layers hold the identity.
// The light a layer looks from; null where the layer is unused (past the
// lights, or one of a directional light's last five).
const Light* layerLight(const std::vector<Light>& lights, int layer);

// A light as the distance shaders read it: its position with w = 1 (a point
// light), or its unit direction of travel with w = 0.
glm::vec4 packedLight(const Light& light);

// The world box about a box of object space placed by placement: its corners'.
Bounds3 placedBox(const Bounds3& box, const Similarity& placement);

std::vector<glm::mat4> blockerShadowViews(const std::vector<Light>& lights, const Bounds3& blockerBounds);

}  // namespace lucent
