#include "core/spatial_order.h"

#include <algorithm>
#include <utility>

namespace lucent {

std::vector<uint32_t> spatialOrder(std::span<const Vec3> positions) {
    Bounds3 box;
    for (const Vec3& p : positions) box.extend(p);
    const Vec3 scale = 1023.0 / glm::max(box.extent(), Vec3(1e-300));
    auto spread = [](uint64_t v) {  // bit k of v to bit 3k
        uint64_t x = v & 0x3ff;
        x = (x | (x << 16)) & 0x030000ff;
        x = (x | (x << 8)) & 0x0300f00f;
        x = (x | (x << 4)) & 0x030c30c3;
        x = (x | (x << 2)) & 0x09249249;
        return x;
    };
    std::vector<std::pair<uint64_t, uint32_t>> keyed(positions.size());
    for (size_t i = 0; i < positions.size(); ++i) {
        const glm::u64vec3 q(glm::clamp((positions[i] - box.min) * scale, Vec3(0.0), Vec3(1023.0)));
        keyed[i] = {spread(q.x) | (spread(q.y) << 1) | (spread(q.z) << 2), uint32_t(i)};
    }
    std::sort(keyed.begin(), keyed.end());
    std::vector<uint32_t> order(positions.size());
    for (size_t i = 0; i < order.size(); ++i) order[i] = keyed[i].second;
    return order;
}

}  // namespace lucent
