// The single-scattering reference in a scene with a refracting boundary: the
// camera ray goes from boundary to boundary as a path of --method path does,
// but where the path tracer picks the reflected or the refracted way by
// Fresnel's odds, the reference follows both, each weighted by its share. Each
// stretch inside an object integrates single scattering with the light arriving
// through the boundary (lightThroughBoundary), so the result is the limit of
// `--method path --max-scatter 1` without its noise. Objects of such a scene
// must not overlap: each boundary separates one medium from the air.
#include <algorithm>

#include "reference/light_arrival.h"
#include "reference/quadrature.h"
#include "reference/reference_renderer.h"
#include "core/refraction.h"

namespace lucent {
namespace {

// Crossings along one branch before it is given up (a ray trapped by total
// internal reflection in a clear object would never end); the path tracer's bound.
constexpr int kMaxBoundaryEvents = 256;
// A branch carrying less than this share of the camera ray's radiance is
// dropped: with the quadrature's relative tolerance of 1e-3 at most, what it
// could add is below what the quadrature already leaves.
constexpr double kLeastWeight = 1e-5;
// Halvings of a quadrature panel through a refracting object. The light found
// through the boundary jumps where the solve finds no ray (shadows behind the
// boundary's curvature, caustics), and on a detailed mesh such points lie
// scattered along the ray: refining each to the 24 halvings of a smooth
// integrand multiplied the solves by thousands. 10 leave a jump's error at a
// thousandth of its panel.
constexpr int kRefractedHalvings = 10;

double largest(const Rgb& c) { return std::max({c.r, c.g, c.b}); }

}  // namespace

Rgb ReferenceRenderer::refractedRadiance(const Vec3& origin, const Vec3& dir, const ReferenceSettings& settings) const {
    const VolumeObject* inside = nullptr;
    for (const VolumeObject& o : objects_)
        if (o.contains(origin)) inside = &o;
    return followRefracted(origin, dir, inside, Rgb(1.0), 0, settings);
}

Rgb ReferenceRenderer::followRefracted(const Vec3& x, const Vec3& w, const VolumeObject* inside, const Rgb& weight,
                                       int events, const ReferenceSettings& settings) const {
    if (events >= kMaxBoundaryEvents || largest(weight) < kLeastWeight) return Rgb(0.0);
    // What the ray meets next: a boundary of the object it is in, or of any object from the air.
    std::optional<BoundaryHit> hit;
    const VolumeObject* hitObject = inside;
    if (inside) {
        hit = nextBoundaryHit(*inside, x, w);
    } else {
        for (const VolumeObject& o : objects_)
            if (const std::optional<BoundaryHit> h = nextBoundaryHit(o, x, w); h && (!hit || h->t < hit->t))
                hit = h, hitObject = &o;
    }
    double tBlocker = kInfinity;
    for (const VolumeObject& o : objects_) tBlocker = std::min(tBlocker, o.firstBlockerHit(x, w));
    const double tEnd = std::min(hit ? hit->t : kInfinity, tBlocker);

    Rgb total(0.0), carried = weight;
    if (inside && tEnd < kInfinity) {
        const VolumeObject& o = *inside;
        const Rgb sigmaT = o.desc().medium.sigmaT;
        const bool refracts = o.desc().medium.ior != 1.0;
        auto integrand = [&](double t) -> Rgb {
            const Vec3 p = x + t * w;
            const Rgb lights = refracts ? lightsThroughBoundary(o, objects_, lights_, p, w) : straightLights(o, p, w);
            return transmittance(sigmaT, o.densityPath(x, w, t)) * o.scattering(p) * lights;
        };
        const double sigmaMax = largest(sigmaT) * o.density().maximum();
        total += weight * integrateIntoDenseMedium(integrand, 0.0, tEnd, sigmaMax, settings.tolerance,
                                                   refracts ? kRefractedHalvings : 24);
        carried *= transmittance(sigmaT, o.densityPath(x, w, tEnd));
    }
    if (!hit || tBlocker < hit->t) return total;  // escapes, or a blocker stops it

    // Fresnel's split at the boundary (as PathTracer's cross(), with both ways kept).
    const double n = hitObject->desc().medium.ior;
    const Vec3 facing = hit->entering ? hit->normal : -hit->normal;
    const double eta = hit->entering ? 1.0 / n : n;
    const double cosine = -glm::dot(w, facing);
    // A shading normal turned away from the ray: it goes through unbent.
    const std::optional<Vec3> refracted = cosine > 0.0 ? refractedDirection(w, facing, eta) : std::optional<Vec3>(w);
    const double reflectance = !refracted ? 1.0 : cosine > 0.0 ? fresnelReflectance(cosine, eta) : 0.0;
    if (reflectance > 0.0)
        total += followRefracted(hit->point, reflectedDirection(w, hit->normal), inside, carried * reflectance,
                                 events + 1, settings);
    if (refracted) {
        // Radiance over n^2 is conserved across the boundary (Veach 1997, 5.2).
        const double crossing = cosine > 0.0 ? (hit->entering ? 1.0 / (n * n) : n * n) : 1.0;
        total += followRefracted(hit->point, *refracted, hit->entering ? hitObject : nullptr,
                                 carried * ((1.0 - reflectance) * crossing), events + 1, settings);
    }
    return total;
}

}  // namespace lucent
