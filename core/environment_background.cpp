#include "core/environment_background.h"

#include <algorithm>
#include <array>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "core/camera_rays.h"
#include "core/refraction.h"

namespace lucent {

namespace {

bool refracts(const VolumeObject& o) { return o.desc().medium.ior != 1.0; }

struct Background {
    const std::vector<VolumeObject>& objects;
    const EnvironmentMap& map;
    const BackgroundEdits& edits;
    const CameraRays rays;
};

// Pixels [x0, x1) of row y, at most MeshRaycaster::kPacket: their rays side by
// side cross each object as one packet (VolumeObject::densityPaths), in the
// object's own world: from where edits place it back to where it was loaded.
void backgroundOfRun(const Background& b, int y, int x0, int x1, Image& image) {
    constexpr size_t kPacket = MeshRaycaster::kPacket;
    const size_t count = size_t(x1 - x0);
    std::array<Vec3, kPacket> dirs, ownOrigins, ownDirs;
    std::array<double, kPacket> paths;
    std::array<Rgb, kPacket> tau;
    for (size_t k = 0; k < count; ++k) {
        dirs[k] = b.rays.direction(x0 + int(k) + 0.5, y + 0.5);
        tau[k] = Rgb(0.0);
    }
    for (size_t i = 0; i < b.objects.size(); ++i) {
        const VolumeObject& o = b.objects[i];
        const Similarity& own = o.placement();
        const Similarity& placed = b.edits.placements.empty() ? own : b.edits.placements[i];
        const Vec3 origin = own.point(placed.inversePoint(b.rays.origin()));
        for (size_t k = 0; k < count; ++k) {
            ownOrigins[k] = origin;
            ownDirs[k] = glm::normalize(own.direction(placed.inverseDirection(dirs[k])));
        }
        if (refracts(o)) {
            for (size_t k = 0; k < count; ++k)
                if (o.boundary().firstHit(ownOrigins[k], ownDirs[k]) < kInfinity) tau[k] = Rgb(kInfinity);
            continue;
        }
        o.densityPaths(std::span(ownOrigins.data(), count), std::span(ownDirs.data(), count), false,
                       std::span(paths.data(), count));
        // Lengths in the object's own world over those in the camera's.
        const double ownPerWorld = own.scale / placed.scale;
        const Rgb sigmaT = b.edits.extinctionScale * o.desc().medium.sigmaT / ownPerWorld;
        // A blocker on the way makes the path infinite: the ray stops there.
        for (size_t k = 0; k < count; ++k) tau[k] += paths[k] == kInfinity ? Rgb(kInfinity) : sigmaT * paths[k];
    }
    const glm::dmat3 unturn = glm::transpose(b.edits.turn);
    for (size_t k = 0; k < count; ++k)
        image.at(x0 + int(k), y) = glm::vec3(b.edits.scale * b.map.radiance(unturn * dirs[k]) * glm::exp(-tau[k]));
}

// One pixel's background in a scene with a refracting object, its objects where
// they were loaded: the camera ray followed through the boundaries with both
// ways kept (core/refraction.h), each branch that leaves every object seeing the map.
glm::vec3 backgroundThroughBoundaries(const Background& b, const Vec3& dir, const VolumeObject* cameraInside) {
    Rgb total(0.0);
    followRayBranches(b.objects, b.rays.origin(), dir, cameraInside, [&](const RayStretch& s) -> Rgb {
        if (!s.inside) {
            if (s.length == kInfinity)
                total += s.weight * b.edits.scale * b.map.radiance(glm::transpose(b.edits.turn) * s.direction);
            return Rgb(1.0);
        }
        if (s.blocked || s.length == kInfinity) return Rgb(0.0);
        const double path = s.inside->densityPath(s.origin, s.direction, s.length);
        return glm::exp(-b.edits.extinctionScale * s.inside->desc().medium.sigmaT * path);
    });
    return glm::vec3(total);
}

bool movedByEdits(const std::vector<VolumeObject>& objects, const BackgroundEdits& edits) {
    if (edits.placements.empty()) return false;
    for (size_t i = 0; i < objects.size(); ++i)
        if (!(edits.placements[i] == objects[i].placement())) return true;
    return false;
}

}  // namespace

Image environmentBackground(const std::vector<VolumeObject>& objects, const EnvironmentMap& map, const Camera& camera,
                            const BackgroundEdits& edits, int threads) {
    const Background b{objects, map, edits, CameraRays(camera)};
    Image image(camera.width, camera.height);
    const int packet = int(MeshRaycaster::kPacket);
    // Through a refracting boundary the ray bends and splits; with every object
    // where it was loaded, it is followed so (backgroundOfRun draws none of it).
    const bool bends = std::any_of(objects.begin(), objects.end(), refracts) && !movedByEdits(objects, edits);
    const VolumeObject* cameraInside = nullptr;
    for (const VolumeObject& o : objects)
        if (bends && o.contains(camera.position)) cameraInside = &o;
    tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
    arena.execute([&] {
        tbb::parallel_for(tbb::blocked_range<int>(0, camera.height), [&](const tbb::blocked_range<int>& rows) {
            for (int y = rows.begin(); y < rows.end(); ++y)
                for (int x = 0; x < camera.width; x += packet) {
                    if (!bends) {
                        backgroundOfRun(b, y, x, std::min(x + packet, camera.width), image);
                        continue;
                    }
                    for (int k = x; k < std::min(x + packet, camera.width); ++k)
                        image.at(k, y) =
                            backgroundThroughBoundaries(b, b.rays.direction(k + 0.5, y + 0.5), cameraInside);
                }
        });
    });
    return image;
}

Image environmentBackground(const LoadedScene& scene, int threads) {
    if (!scene.environment || !scene.desc.render.background) return {};
    return environmentBackground(scene.objects, *scene.environment, scene.desc.camera, BackgroundEdits{}, threads);
}

}  // namespace lucent
