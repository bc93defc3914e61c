#include "runtime/internal/traced_light.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace lucent {

std::vector<glm::vec4> tracedOpticalDepths(const std::vector<TracedVolume>& volumes, const SampleSet& samples,
                                           const Similarity& placement, const std::vector<Light>& lights) {
    const size_t lightCount = lights.size();
    std::vector<glm::vec4> depths(samples.size() * lightCount, glm::vec4(0.0f));
    if (depths.empty()) return depths;
    for (const TracedVolume& v : volumes) v.volume->boundary();  // built once here, not raced for by the rays
    tbb::parallel_for(tbb::blocked_range<size_t>(0, samples.size(), 256), [&](const tbb::blocked_range<size_t>& r) {
        for (size_t i = r.begin(); i != r.end(); ++i) {
            const Vec3 x = placement.point(Vec3(samples.positions[i]));
            for (size_t j = 0; j < lightCount; ++j) {
                const Light& light = lights[j];
                Vec3 dir;
                double reach = kInfinity;
                if (light.type == Light::Type::Point) {
                    reach = glm::length(light.position - x);
                    if (!(reach > 0.0)) continue;  // a light at the centre: nothing in between
                    dir = (light.position - x) / reach;
                } else {
                    const double length = glm::length(light.direction);
                    if (!(length > 0.0)) continue;
                    dir = -light.direction / length;
                }
                Rgb tau(0.0);
                bool blocked = false;
                for (const TracedVolume& v : volumes) {
                    // The ray in the volume's own world: through its object space.
                    const Similarity& own = v.volume->placement();
                    const double toOwn = own.scale / v.placement.scale;  // its lengths per world length
                    const Vec3 origin = own.point(v.placement.inversePoint(x));
                    const Vec3 ownDir = own.direction(v.placement.inverseDirection(dir));
                    const double path = v.volume->densityPath(origin, ownDir, reach * toOwn);
                    if (path == kInfinity) {
                        blocked = true;
                        break;
                    }
                    tau += v.volume->desc().medium.sigmaT * (path / toOwn);
                }
                depths[i * lightCount + j] =
                    blocked ? glm::vec4(0.0f, 0.0f, 0.0f, 1.0f) : glm::vec4(glm::vec3(tau), 0.0f);
            }
        }
    });
    return depths;
}

}  // namespace lucent
