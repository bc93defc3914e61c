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

// Halvings of a quadrature panel through a refracting object. The light found
// through the boundary jumps where the solve finds no ray (shadows behind the
// boundary's curvature, caustics), and on a detailed mesh such points lie
// scattered along the ray: refining each to the 24 halvings of a smooth
// integrand multiplied the solves by thousands. 10 leave a jump's error at a
// thousandth of its panel.
constexpr int kRefractedHalvings = 10;

double largest(const Rgb& c) { return std::max({c.r, c.g, c.b}); }

}  // namespace

// Each branch is dropped below kLeastBranchWeight (core/refraction.h) of the
// camera ray's radiance: with the quadrature's relative tolerance of 1e-3 at
// most, what it could add is below what the quadrature already leaves.
Rgb ReferenceRenderer::refractedRadiance(const Vec3& origin, const Vec3& dir, const ReferenceSettings& settings) const {
    const VolumeObject* inside = nullptr;
    for (const VolumeObject& o : objects_)
        if (o.contains(origin)) inside = &o;
    Rgb total(0.0);
    followRayBranches(objects_, origin, dir, inside, [&](const RayStretch& s) -> Rgb {
        if (!s.inside) {
            // Leaving every object: the environment behind, with the background on.
            if (s.length == kInfinity && environment_ && scene_.render.background)
                total += s.weight * environment_->radiance(s.direction);
            return Rgb(1.0);
        }
        if (s.length == kInfinity) return Rgb(0.0);  // a boundary with a gap: nothing is known beyond it
        const VolumeObject& o = *s.inside;
        const Rgb sigmaT = o.desc().medium.sigmaT;
        const bool refracts = o.desc().medium.ior != 1.0;
        auto integrand = [&](double t) -> Rgb {
            const Vec3 p = s.origin + t * s.direction;
            if (magnitude(o.scattering(p)) == 0.0) return Rgb(0.0);
            const Rgb lights = refracts ? lightsThroughBoundary(o, objects_, lights_, p, s.direction)
                                        : straightLights(o, p, s.direction);
            return transmittance(sigmaT, o.densityPath(s.origin, s.direction, t)) * o.scattering(p) * lights;
        };
        const double sigmaMax = largest(sigmaT) * o.density().maximum();
        total += s.weight * integrateIntoDenseMedium(integrand, 0.0, s.length, sigmaMax, settings.tolerance,
                                                     refracts ? kRefractedHalvings : 24);
        return transmittance(sigmaT, o.densityPath(s.origin, s.direction, s.length));
    });
    return total;
}

}  // namespace lucent
