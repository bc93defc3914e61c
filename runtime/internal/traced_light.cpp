#include "runtime/internal/traced_light.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>

#include "core/mesh_raycaster.h"
#include "core/refraction.h"
#include "core/spatial_order.h"
#include "core/sphere_light.h"

namespace lucent {
namespace {

// The optical depth from x (renderer's world) along unit dir over reach, summed
// over the volumes but skip, or that a blocker stops the light.
struct Depth {
    Rgb tau{0.0};
    bool blocked = false;
};
Depth depthAlong(const std::vector<TracedVolume>& volumes, const TracedVolume* skip, const Vec3& x, const Vec3& dir,
                 double reach) {
    Depth d;
    for (const TracedVolume& v : volumes) {
        if (&v == skip) continue;
        // The ray in the volume's own world: through its object space.
        const Similarity& own = v.volume->placement();
        const double toOwn = own.scale / v.placement.scale;  // its lengths per world length
        const Vec3 origin = own.point(v.placement.inversePoint(x));
        const Vec3 ownDir = own.direction(v.placement.inverseDirection(dir));
        const double path = v.volume->densityPath(origin, ownDir, reach * toOwn);
        if (path == kInfinity) {
            d.blocked = true;
            return d;
        }
        d.tau += v.volume->desc().medium.sigmaT * (path / toOwn);
    }
    return d;
}

// A sphere light's soft shadow: its cone on kSoftStrata^2 strata, turned per
// sample so that the strata's pattern does not print across the object, and the
// transmittance averaged; packed as the depth whose exponential is that mean.
constexpr int kSoftStrata = 4;

Depth softDepth(const std::vector<TracedVolume>& volumes, const Vec3& x, const Light& light, size_t sample) {
    const std::optional<SphereLightCone> cone = sphereLightCone(light.position, light.radius, x);
    if (!cone) return Depth{Rgb(0.0), true};  // inside the light: it sends nothing there
    const double turn = std::fmod(double(sample) * 0.6180339887498949, 1.0);
    Rgb mean(0.0);
    for (int k = 0; k < kSoftStrata * kSoftStrata; ++k) {
        const double u = (k % kSoftStrata + 0.5) / kSoftStrata;
        const double v = std::fmod((k / kSoftStrata + 0.5) / kSoftStrata + turn, 1.0);
        const Vec3 w = coneDirection(*cone, u, v);
        const Depth d = depthAlong(volumes, nullptr, x, w, distanceToSphere(x, w, light.position, light.radius));
        if (!d.blocked) mean += glm::exp(-d.tau) / double(kSoftStrata * kSoftStrata);
    }
    if (std::max({mean.r, mean.g, mean.b}) <= 0.0) return Depth{Rgb(0.0), true};
    return Depth{-glm::log(glm::max(mean, Rgb(1e-300))), false};
}

glm::vec4 packed(const Depth& d) {
    return d.blocked ? glm::vec4(0.0f, 0.0f, 0.0f, 1.0f) : glm::vec4(glm::vec3(d.tau), 0.0f);
}

// The light in the volume's own world, for a renderer that stands it at
// placement, with a power of 1: what arrives is then per unit of its power.
Light unitLightInOwnWorld(const Light& light, const TracedVolume& v) {
    const Similarity& own = v.volume->placement();
    Light l = light;
    l.power = Rgb(1.0);
    if (l.type == Light::Type::Point) l.position = own.point(v.placement.inversePoint(light.position));
    if (l.spot) l.spot->axis = glm::normalize(own.direction(v.placement.inverseDirection(light.spot->axis)));
    if (l.type == Light::Type::Directional) l.direction = own.direction(v.placement.inverseDirection(light.direction));
    return l;
}

// Up to MeshRaycaster::kPacket rays from samples' centres towards one light,
// traced through every volume as one packet a volume (VolumeObject::densityPaths).
struct RayPacket {
    std::array<Vec3, MeshRaycaster::kPacket> origin, dir;
    std::array<double, MeshRaycaster::kPacket> reach;
    std::array<size_t, MeshRaycaster::kPacket> sample;
    std::array<Depth, MeshRaycaster::kPacket> depth;
    size_t count = 0;

    size_t size() const { return count; }
    void clear() { count = 0; }

    // The ray from x towards a point or directional light; none where the light
    // sits at x or has no direction (their depth stays 0, as one ray alone).
    void addTowards(const Light& light, const Vec3& x, size_t i) {
        Vec3 d;
        double r = kInfinity;
        if (light.type == Light::Type::Point) {
            r = glm::length(light.position - x);
            if (!(r > 0.0)) return;
            d = (light.position - x) / r;
        } else {
            const double length = glm::length(light.direction);
            if (!(length > 0.0)) return;
            d = -light.direction / length;
        }
        origin[count] = x;
        dir[count] = d;
        reach[count] = r;
        sample[count] = i;
        ++count;
    }

    // depthAlong for every ray, a packet a volume.
    void trace(const std::vector<TracedVolume>& volumes) {
        if (count == 0) return;
        std::array<Vec3, MeshRaycaster::kPacket> ownOrigin, ownDir;
        std::array<double, MeshRaycaster::kPacket> ownReach, path;
        depth.fill(Depth{});
        for (const TracedVolume& v : volumes) {
            const Similarity& own = v.volume->placement();
            const double toOwn = own.scale / v.placement.scale;  // its lengths per world length
            for (size_t k = 0; k < count; ++k) {
                ownOrigin[k] = own.point(v.placement.inversePoint(origin[k]));
                ownDir[k] = own.direction(v.placement.inverseDirection(dir[k]));
                ownReach[k] = reach[k] * toOwn;
            }
            v.volume->densityPaths(std::span(ownOrigin.data(), count), std::span(ownDir.data(), count), false,
                                   std::span(path.data(), count), std::span(ownReach.data(), count));
            for (size_t k = 0; k < count; ++k) {
                if (path[k] == kInfinity) depth[k].blocked = true;
                if (!depth[k].blocked) depth[k].tau += v.volume->desc().medium.sigmaT * (path[k] / toOwn);
            }
        }
    }
};

void forEachSample(size_t count, const std::function<void(size_t)>& body) {
    tbb::parallel_for(tbb::blocked_range<size_t>(0, count, 64), [&](const tbb::blocked_range<size_t>& r) {
        for (size_t i = r.begin(); i != r.end(); ++i) body(i);
    });
}

}  // namespace

std::vector<glm::vec4> tracedOpticalDepths(const std::vector<TracedVolume>& volumes, const SampleSet& samples,
                                           const Similarity& placement, const std::vector<Light>& lights) {
    const size_t lightCount = lights.size();
    std::vector<glm::vec4> depths(samples.size() * lightCount, glm::vec4(0.0f));
    if (depths.empty()) return depths;
    for (const TracedVolume& v : volumes) v.volume->boundary();  // built once here, not raced for by the rays
    std::vector<Vec3> centres(samples.size());
    for (size_t i = 0; i < centres.size(); ++i) centres[i] = placement.point(Vec3(samples.positions[i]));
    // Neighbouring samples in one packet: their rays to a light run side by side.
    const std::vector<uint32_t> order = spatialOrder(centres);
    const size_t P = MeshRaycaster::kPacket, packets = (order.size() + P - 1) / P;
    tbb::parallel_for(tbb::blocked_range<size_t>(0, packets, 4), [&](const tbb::blocked_range<size_t>& range) {
        RayPacket rays;
        for (size_t packet = range.begin(); packet != range.end(); ++packet) {
            const size_t first = packet * P, count = std::min(P, order.size() - first);
            for (size_t j = 0; j < lightCount; ++j) {
                const Light& light = lights[j];
                if (light.type == Light::Type::Point && light.radius > 0.0) {
                    for (size_t k = 0; k < count; ++k) {
                        const size_t i = order[first + k];
                        depths[i * lightCount + j] = packed(softDepth(volumes, centres[i], light, i));
                    }
                    continue;
                }
                rays.clear();
                for (size_t k = 0; k < count; ++k) rays.addTowards(light, centres[order[first + k]], order[first + k]);
                rays.trace(volumes);
                for (size_t r = 0; r < rays.size(); ++r)
                    depths[rays.sample[r] * lightCount + j] = packed(rays.depth[r]);
            }
        }
    });
    return depths;
}

std::vector<glm::vec4> tracedRefractedLight(const std::vector<TracedVolume>& volumes, size_t own,
                                            const SampleSet& samples, const std::vector<Light>& lights) {
    const size_t lightCount = lights.size();
    std::vector<glm::vec4> records(2 * samples.size() * lightCount, glm::vec4(0.0f));
    if (records.empty()) return records;
    for (const TracedVolume& v : volumes) v.volume->boundary();
    const TracedVolume& o = volumes.at(own);
    const Similarity& ownWorld = o.volume->placement();
    const double toOwn = ownWorld.scale / o.placement.scale;
    std::vector<Light> ownLights;
    for (const Light& light : lights) ownLights.push_back(unitLightInOwnWorld(light, o));
    forEachSample(samples.size(), [&](size_t i) {
        // The sample in the volume's own world (samples are in object space).
        const Vec3 x = ownWorld.point(Vec3(samples.positions[i]));
        for (size_t j = 0; j < lightCount; ++j) {
            const std::optional<RefractedArrival> a = lightThroughBoundary(*o.volume, ownLights[j], x);
            if (!a) continue;  // records of zero: no light
            // Inside along the refracted way, then on through the others from where it entered.
            const double path = o.volume->densityPath(x, a->toLight, a->inside);
            Depth d;
            if (path == kInfinity) {
                d.blocked = true;
            } else {
                const Vec3 entry = o.placement.point(ownWorld.inversePoint(a->entry));
                const Vec3 outward = o.placement.direction(ownWorld.inverseDirection(a->outward));
                d = depthAlong(volumes, &o, entry, outward, a->outside / toOwn);
                d.tau += o.volume->desc().medium.sigmaT * (path / toOwn);
            }
            // A point light's irradiance is per unit area of the volume's world: toOwn^2
            // of it per unit area of the renderer's. A directional one's is a ratio of areas.
            const double perPower = a->irradiance.r * (lights[j].type == Light::Type::Point ? toOwn * toOwn : 1.0);
            const Vec3 toLight = o.placement.direction(ownWorld.inverseDirection(a->toLight));
            const size_t k = 2 * (i * lightCount + j);
            records[k] = packed(d);
            records[k + 1] = glm::vec4(glm::vec3(toLight), float(perPower));
        }
    });
    return records;
}

}  // namespace lucent
