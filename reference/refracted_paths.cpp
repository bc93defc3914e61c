// The path tracer in a scene with a refracting boundary (an object whose ior
// differs from 1): paths go from boundary to boundary. Inside an object,
// collisions come by delta tracking up to the boundary ahead; at the boundary
// the path is reflected with Fresnel's probability and refracted otherwise, so
// Fresnel's factor is the odds and not a weight. Radiance divided by n^2 is
// conserved across a boundary (Veach 1997, 5.2): a camera path that goes into a
// medium of index n carries radiance n^2 times larger there, which the
// crossing's factor 1/n^2 brings back (n^2 on the way out). Objects of such a
// scene must not overlap: each boundary separates one medium from the air.
#include <algorithm>
#include <cmath>

#include "core/environment_map.h"
#include "core/math.h"
#include "reference/light_arrival.h"
#include "reference/path_channels.h"
#include "reference/quadrature.h"
#include "reference/path_tracer.h"
#include "core/refraction.h"

namespace lucent {
namespace {

// Boundary crossings a path may make before it is given up (a ray trapped by
// total internal reflection in a clear box would never end).
constexpr int kMaxBoundaryEvents = 256;

// Reflects or refracts w at the boundary by Fresnel's odds and moves the path
// to the side it goes on; returns what the crossing multiplies the radiance
// carried back along the path by.
double cross(const BoundaryHit& hit, const VolumeObject& object, Vec3& w, const VolumeObject*& inside,
             PathSampler& rng) {
    const double n = object.desc().medium.ior;
    const Vec3 facing = hit.entering ? hit.normal : -hit.normal;
    const double eta = hit.entering ? 1.0 / n : n;
    const double cosine = -glm::dot(w, facing);
    // A shading normal turned away from the ray: let it through unbent.
    const std::optional<Vec3> refracted = cosine > 0.0 ? refractedDirection(w, facing, eta) : std::optional<Vec3>(w);
    const double reflectance = cosine > 0.0 ? fresnelReflectance(cosine, eta) : 0.0;
    if (!refracted || rng.uniform() < reflectance) {
        w = reflectedDirection(w, hit.normal);
        return 1.0;
    }
    w = *refracted;
    inside = hit.entering ? &object : nullptr;
    return cosine > 0.0 ? (hit.entering ? 1.0 / (n * n) : n * n) : 1.0;
}

// Whether the solve for light arriving at x from outside along -w (a
// directional light, as gatherLightsRefracted draws the environment's) finds
// the ray that leaves o at exitPoint: then that collision gathered this way out.
bool solvedAlike(const VolumeObject& o, const Vec3& x, const Vec3& w, const Vec3& exitPoint) {
    Light light;
    light.type = Light::Type::Directional;
    light.direction = -w;
    const std::optional<RefractedArrival> a = lightThroughBoundary(o, light, x);
    return a && glm::length(a->entry - exitPoint) < 1e-5 * o.boundary().bounds().diagonal();
}

}  // namespace

Rgb PathTracer::gatherLightsRefracted(const VolumeObject& object, const Vec3& x, const Vec3& dir,
                                      PathSampler& rng) const {
    // In an index-matched object, the lights only: the environment is met by escaping paths.
    if (object.desc().medium.ior == 1.0) return gatherSceneLights(object, x, dir, rng);
    Rgb sum = lightsThroughBoundaryByRoulette(object, objects_, scene_.lights, x, dir, [&] { return rng.uniform(); });
    if (!environment_) return sum;
    // The environment through the boundary: one direction outside drawn from the
    // map, taken as a directional light of radiance over density (its estimate
    // of the integral over the sphere), solved for as the lights are. A path that
    // leaves after this collision by one refraction, with no reflection on the
    // way, by the ray this solve finds, brings what this gathers: it counts
    // none of it (refractedRadiance).
    // Without this, a small sun outside was met by escaping paths alone: 89%
    // noise per pixel at 64 paths on a sphere of ior 1.5, 9% index-matched.
    const double u1 = rng.uniform(), u2 = rng.uniform();
    const EnvironmentMap::Sample s = environment_->sample(u1, u2);
    if (!(s.pdf > 0.0) || magnitude(s.radiance) == 0.0) return sum;
    Light sun;
    sun.type = Light::Type::Directional;
    sun.direction = -s.toward;
    sun.power = s.radiance / s.pdf;
    return sum + lightsThroughBoundary(object, objects_, {sun}, x, dir);
}

PathTracer::Ahead PathTracer::ahead(const VolumeObject* inside, const Vec3& x, const Vec3& w, PathSampler& rng,
                                    int channel) const {
    Ahead a;
    if (inside) {
        a.boundary = nextBoundaryHit(*inside, x, w);
        a.object = inside;
    } else {
        for (const VolumeObject& o : objects_) {
            const std::optional<BoundaryHit> h = nextBoundaryHit(o, x, w);
            if (h && (!a.boundary || h->t < a.boundary->t)) a.boundary = h, a.object = &o;
        }
    }
    const double tBlocker = blockerDistance(x, w), tBoundary = a.boundary ? a.boundary->t : kInfinity;
    if (inside)
        a.collision = sampleCollisionIn(*inside, x, w, Interval{0.0, std::min(tBoundary, tBlocker)}, rng, channel);
    a.blocked = tBlocker < tBoundary;
    return a;
}

Rgb PathTracer::refractedRadiance(const Vec3& origin, const Vec3& dir, PathSampler& rng, const PathSettings& settings,
                                  int channel) const {
    Rgb total = masked(surfaceTerm(origin, dir, blockerDistance(origin, dir), settings), channel);
    const VolumeObject* inside = containing(origin);
    Vec3 x = origin, w = dir;
    Rgb throughput(1.0);
    int collisions = 0;
    // Since the last collision, in a refracting object, the path has only gone
    // straight out (refracted once, then on through index-matched objects).
    bool gathered = false;
    Vec3 collision(0.0), exitPoint(0.0);
    const VolumeObject* collidedIn = nullptr;
    for (int events = 0; events < kMaxBoundaryEvents;) {
        const Ahead a = ahead(inside, x, w, rng, channel);
        if (a.collision) {
            x += *a.collision * w;
            // The collision estimator, as in radiance(): the albedo is the collision's weight.
            throughput *= masked(inside->desc().medium.albedo, channel);
            total += throughput * masked(gatherLightsRefracted(*inside, x, w, rng), channel);
            gathered = inside->desc().medium.ior != 1.0;
            collision = x;
            collidedIn = inside;
            if (++collisions >= settings.maxScatter) break;
            if (collisions > 3 && !survivesRoulette(throughput, rng)) break;
            double xi1, xi2;
            rng.directionUniforms(xi1, xi2);
            w = sampleHenyeyGreenstein(w, inside->desc().medium.g, xi1, xi2);
            continue;
        }
        if (a.blocked) break;  // a blocker absorbs it
        if (!a.boundary) {
            // It leaves. The environment it meets is the last collision's to
            // gather when it left by the one refraction that collision's solve
            // finds for this direction; otherwise (reflected inside first, from an
            // index-matched object, or by a refraction the solve misses or does
            // not find) this is the whole estimate, unweighed.
            if (!gathered || !solvedAlike(*collidedIn, collision, w, exitPoint))
                total += throughput * masked(escaped(w, w, 0.0, collisions > 0, false), channel);
            break;
        }
        x = a.boundary->point;
        const VolumeObject* before = inside;
        throughput *= cross(*a.boundary, *a.object, w, inside, rng);
        // Out by a refraction, or on through an index-matched object (its
        // attenuation the gathered light counts): still the collision's straight way out.
        const bool out = inside == nullptr && before != nullptr;
        if (!out && !(inside != nullptr && before == nullptr && inside->desc().medium.ior == 1.0)) gathered = false;
        if (out && before->desc().medium.ior != 1.0) exitPoint = x;
        ++events;
    }
    return total;
}

PathTracer::Exit PathTracer::refractedWalk(const Vec3& origin, const Vec3& dir, PathSampler& rng, int maxScatter,
                                           int channel) const {
    Exit exit;
    const VolumeObject* inside = containing(origin);
    Vec3 x = origin, w = dir;
    for (int events = 0; events < kMaxBoundaryEvents;) {
        const Ahead a = ahead(inside, x, w, rng, channel);
        if (a.collision) {
            if (exit.collisions == maxScatter) return exit;
            x += *a.collision * w;
            exit.weight *= inside->desc().medium.albedo;
            ++exit.collisions;
            double xi1, xi2;
            rng.directionUniforms(xi1, xi2);
            w = sampleHenyeyGreenstein(w, inside->desc().medium.g, xi1, xi2);
            continue;
        }
        if (a.blocked) return exit;  // absorbed by a blocker
        if (!a.boundary) {
            exit.escaped = true;
            exit.position = x;
            exit.direction = w;
            return exit;
        }
        x = a.boundary->point;
        cross(*a.boundary, *a.object, w, inside, rng);
        ++events;
    }
    return exit;  // trapped: counted as not escaped
}

}  // namespace lucent
