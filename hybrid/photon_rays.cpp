#include "hybrid/photon_rays.h"

#include <algorithm>
#include <cmath>

#include "core/rng.h"

namespace lucent::hybrid {

namespace {

constexpr int kDiskStrata = 4;

// An orthonormal basis around w.
void basis(const Vec3& w, Vec3& u, Vec3& v) {
    u = glm::normalize(std::abs(w.x) > 0.5 ? glm::cross(w, Vec3(0, 1, 0)) : glm::cross(w, Vec3(1, 0, 0)));
    v = glm::cross(w, u);
}

}  // namespace

RayMap rayMapFor(const std::vector<Light>& lights, const GridShape& grid, int count, uint64_t seed) {
    RayMap map;
    const Bounds3 box = grid.bounds();
    const Vec3 centre = box.center();
    const double radius = 0.5 * box.diagonal();
    const int side = std::max(1, int(std::lround(std::sqrt(double(count)))));
    Rng rng(seed, 0x7261796d6170ull);  // "raymap"
    Rng disk(seed, 0x6469736bull);     // "disk": a sphere light's, apart so that the rays' strata stay as they were
    for (const Light& light : lights) {
        Vec3 w = light.type == Light::Type::Point ? centre - light.position : light.direction;
        const double distance = glm::length(w);
        if (light.type == Light::Type::Point && distance <= 0.0) w = Vec3(0, 0, 1);
        w = glm::normalize(w);
        Vec3 u, v;
        basis(w, u, v);
        // A point light inside the bounding sphere sends rays everywhere. A sphere
        // light's rays start up to its radius off the centre: its cone is wider.
        const double reach = radius + (light.type == Light::Type::Point ? light.radius : 0.0);
        const double cosMax = light.type == Light::Type::Point && distance > reach
                                  ? std::sqrt(1.0 - (reach / distance) * (reach / distance))
                                  : -1.0;
        const double share = light.type == Light::Type::Point ? 2.0 * kPi * (1.0 - cosMax) / (side * side)
                                                              : 4.0 * radius * radius / (side * side);
        // A sphere light's rays along dir leave its disk across dir uniformly (its
        // radiance is the same over the disk it shows): so do the photons, kDiskStrata
        // of them per direction, one from each stratum of the disk (two rings of equal
        // area, two halves around). With one ray a direction, at a random point of
        // the disk, lbl's image under a sphere light of radius 1 over a slab was
        // 3.5% noisier per pixel from seed to seed (tests/methods/sphere_light_gl_test.cpp).
        const bool sphere = light.type == Light::Type::Point && light.radius > 0.0;
        const int perDirection = sphere ? kDiskStrata : 1;
        const Rgb power = light.power * share / double(perDirection);
        for (int i = 0; i < side; ++i)
            for (int j = 0; j < side; ++j) {
                // The rays of one direction differ only in where they leave the disk, so
                // that as its radius shrinks they become the point light's ray.
                const double a = (i + rng.uniform()) / side, b = (j + rng.uniform()) / side;
                for (int k = 0; k < perDirection; ++k) {
                    Vec3 origin, dir;
                    if (light.type == Light::Type::Point) {
                        const double cosT = 1.0 - a * (1.0 - cosMax),
                                     sinT = std::sqrt(std::max(0.0, 1.0 - cosT * cosT));
                        const double phi = 2.0 * kPi * b;
                        dir = cosT * w + sinT * (std::cos(phi) * u + std::sin(phi) * v);
                        origin = light.position;
                        if (sphere) {
                            Vec3 du, dv;
                            basis(dir, du, dv);
                            const double r = light.radius * std::sqrt((k / 2 + disk.uniform()) / 2.0),
                                         t = kPi * (k % 2 + disk.uniform());
                            origin += r * (std::cos(t) * du + std::sin(t) * dv);
                        }
                    } else {
                        origin = centre - 2.0 * radius * w + radius * ((2.0 * a - 1.0) * u + (2.0 * b - 1.0) * v);
                        dir = w;
                    }
                    double t = 0.0, exit = kInfinity;
                    if (!clipToBox(box, origin, dir, t, exit)) continue;  // t: where the ray enters the box
                    // Just inside the box, so the first step lands in a voxel of the grid.
                    const Vec3 start = origin + (t + 1e-4 * grid.voxel) * dir;
                    clshared::PhotonRay ray{};
                    ray.position = {{float(start.x), float(start.y), float(start.z), 1.0f}};
                    ray.velocity = {{float(dir.x), float(dir.y), float(dir.z), 0.0f}};  // n = 1 outside
                    const Rgb sent = power * spotFalloff(light, dir);
                    if (std::max({sent.r, sent.g, sent.b}) <= 0.0) continue;  // outside a spot's cone
                    ray.power = {{float(sent.r), float(sent.g), float(sent.b), 0.0f}};
                    map.rays.push_back(ray);
                    map.emitted += sent;
                }
            }
    }
    return map;
}

}  // namespace lucent::hybrid
