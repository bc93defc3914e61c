#include "core/environment_background.h"

#include <array>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "core/camera_rays.h"

namespace lucent {

namespace {

bool refracts(const VolumeObject& o) { return o.desc().medium.ior != 1.0; }

// Pixels [x0, x1) of row y, at most MeshRaycaster::kPacket: their rays side by
// side cross each object as one packet (VolumeObject::densityPaths).
void backgroundOfRun(const LoadedScene& scene, const CameraRays& rays, int y, int x0, int x1, Image& image) {
    constexpr size_t kPacket = MeshRaycaster::kPacket;
    const size_t count = size_t(x1 - x0);
    std::array<Vec3, kPacket> origins, dirs;
    std::array<double, kPacket> paths;
    std::array<Rgb, kPacket> tau;
    for (size_t k = 0; k < count; ++k) {
        origins[k] = rays.origin();
        dirs[k] = rays.direction(x0 + int(k) + 0.5, y + 0.5);
        tau[k] = Rgb(0.0);
    }
    for (const VolumeObject& o : scene.objects) {
        if (refracts(o)) {
            for (size_t k = 0; k < count; ++k)
                if (o.boundary().firstHit(origins[k], dirs[k]) < kInfinity) tau[k] = Rgb(kInfinity);
            continue;
        }
        o.densityPaths(std::span(origins.data(), count), std::span(dirs.data(), count), false,
                       std::span(paths.data(), count));
        // A blocker on the way makes the path infinite: the ray stops there.
        for (size_t k = 0; k < count; ++k)
            tau[k] += paths[k] == kInfinity ? Rgb(kInfinity) : o.desc().medium.sigmaT * paths[k];
    }
    for (size_t k = 0; k < count; ++k)
        image.at(x0 + int(k), y) = glm::vec3(scene.environment->radiance(dirs[k]) * glm::exp(-tau[k]));
}

}  // namespace

Image environmentBackground(const LoadedScene& scene, int threads) {
    if (!scene.environment || !scene.desc.render.background) return {};
    const Camera& camera = scene.desc.camera;
    const CameraRays rays(camera);
    Image image(camera.width, camera.height);
    const int packet = int(MeshRaycaster::kPacket);
    tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
    arena.execute([&] {
        tbb::parallel_for(tbb::blocked_range<int>(0, camera.height), [&](const tbb::blocked_range<int>& rows) {
            for (int y = rows.begin(); y < rows.end(); ++y)
                for (int x = 0; x < camera.width; x += packet)
                    backgroundOfRun(scene, rays, y, x, std::min(x + packet, camera.width), image);
        });
    });
    return image;
}

std::vector<std::string> environmentBackgroundLimitations(const LoadedScene& scene) {
    std::vector<std::string> out;
    if (!scene.environment || !scene.desc.render.background) return out;
    for (const VolumeObject& o : scene.objects)
        if (refracts(o))
            out.push_back("object '" + o.desc().name +
                          "' refracts: the environment behind it is not drawn through it (\"background\": true; "
                          "--method path bends it through the boundary)");
    return out;
}

}  // namespace lucent
