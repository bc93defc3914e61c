#include "reference/reference_renderer.h"

#include <array>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cstdio>

#include "core/error.h"

#include "core/camera_rays.h"
#include "core/progress.h"
#include "reference/light_arrival.h"
#include "reference/path_tracer.h"
#include "reference/quadrature.h"
#include "reference/surface_reflection.h"

namespace lucent {

ReferenceRenderer::ReferenceRenderer(const SceneDesc& scene, const std::vector<VolumeObject>& objects,
                                     const EnvironmentMap* environment)
    : scene_(scene),
      objects_(objects),
      environment_(environment),
      lights_(withEnvironmentLights(scene.lights, environment, kReferenceEnvironmentDirections)) {
    for (const VolumeObject& o : objects_) refracting_ = refracting_ || o.desc().medium.ior != 1.0;
    if (environment_) environmentSamples_ = environment_->stratifiedSamples(kReferenceEnvironmentDirections);
}

double ReferenceRenderer::densityPathAllObjects(const Vec3& origin, const Vec3& dir, double tMax) const {
    double path = 0.0;
    for (const auto& o : objects_) path += o.densityPath(origin, dir, tMax);
    return path;
}

// sigma_s(x) sum_j p E_j(x) T(x, l_j): light scattered at x towards the viewer,
// before attenuation on the way to the viewer. viewDir points from the camera to x.
Rgb ReferenceRenderer::inScattered(const VolumeObject& object, const Vec3& x, const Vec3& viewDir) const {
    const Rgb sigmaS = object.scattering(x);
    if (magnitude(sigmaS) == 0.0) return Rgb(0.0);
    return sigmaS * straightLights(object, x, viewDir);
}

namespace {

// The midpoint rule over a sphere light's cone, on kSphereLightStrata^2 strata
// uniform in solid angle. Where a blocker's edge crosses the cone, a stratum
// whose light is blocked and a neighbour's that is not are each integrated
// again on as many sub-strata: the rule alone was 3% off in a plate's
// penumbra (tests/reference/sphere_light_penumbra_test.cpp), as its error
// there falls only as one over the strata per axis.
template <class Arriving>
Rgb sphereLightCone(const Light& light, const Arriving& arriving) {
    constexpr int n = kSphereLightStrata;
    std::array<Rgb, n * n> strata;
    for (int k = 0; k < n * n; ++k) strata[k] = arriving(light, (k % n + 0.5) / n, (k / n + 0.5) / n);
    // Stratum (i, j) spans the cone's rings i (u, from the axis out) and sectors j
    // (v, around it, so sector n - 1 meets sector 0); the first ring's strata all meet at the axis.
    const auto dark = [&](int i, int j) { return magnitude(strata[((j + n) % n) * n + i]) == 0.0; };
    bool innerRingMixed = false;
    for (int j = 1; j < n; ++j) innerRingMixed = innerRingMixed || dark(0, j) != dark(0, 0);
    Rgb sum(0.0);
    for (int k = 0; k < n * n; ++k) {
        const int i = k % n, j = k / n;
        const bool edge = (i == 0 && innerRingMixed) || (i > 0 && dark(i - 1, j) != dark(i, j)) ||
                          (i + 1 < n && dark(i + 1, j) != dark(i, j)) || dark(i, j - 1) != dark(i, j) ||
                          dark(i, j + 1) != dark(i, j);
        if (!edge) {
            sum += strata[k];
            continue;
        }
        for (int m = 0; m < n * n; ++m)
            sum += arriving(light, (i + (m % n + 0.5) / n) / n, (j + (m / n + 0.5) / n) / n) / double(n * n);
    }
    return sum / double(n * n);
}

}  // namespace

Rgb ReferenceRenderer::straightLights(const VolumeObject& object, const Vec3& x, const Vec3& viewDir) const {
    // Light from (u, v) of a light's directions: phase p between the light's
    // propagation direction (-toLight) and the view's (-viewDir), times E T.
    const auto arriving = [&](const Light& light, double u, double v) {
        const std::optional<LightArrival> a = lightArrivingAt(light, x, u, v);
        if (!a) return Rgb(0.0);
        const double phase = henyeyGreenstein(glm::dot(a->toLight, viewDir), object.desc().medium.g);
        return phase * a->irradiance * transmittanceToLight(objects_, x, *a);
    };
    Rgb sum(0.0);
    for (const Light& light : scene_.lights)
        sum += light.radius > 0.0 ? sphereLightCone(light, arriving) : arriving(light, 0.5, 0.5);
    return environment_ ? sum + straightEnvironment(object, x, viewDir) : sum;
}

// Multiple importance sampling with both point sets of equal size N (the
// balance heuristic, Veach 1997, 9.2.2): each direction adds f / (N (p_map +
// p_phase)). With the map's directions alone the reference was 10% from the
// path tracer at g = 0.9 and 22% at g = -0.9 (a sphere under a sky with a sun;
// within 2% for |g| up to 0.8): a peaked lobe saw the map's directions one by one.
Rgb ReferenceRenderer::straightEnvironment(const VolumeObject& object, const Vec3& x, const Vec3& viewDir) const {
    const double g = object.desc().medium.g;
    const double count = double(environmentSamples_.size());
    const auto add = [&](const Vec3& toward, const Rgb& radiance, double mapPdf) {
        const double phase = henyeyGreenstein(glm::dot(toward, viewDir), g);
        if (magnitude(radiance) == 0.0 || !(mapPdf + phase > 0.0)) return Rgb(0.0);
        const LightArrival arrival{toward, kInfinity, radiance};
        return phase * radiance * transmittanceToLight(objects_, x, arrival) / (count * (mapPdf + phase));
    };
    Rgb sum(0.0);
    for (const EnvironmentMap::Sample& s : environmentSamples_) sum += add(s.toward, s.radiance, s.pdf);
    // The phase function's directions: the light's direction towards its source
    // about the view's, at cosine mu with the density p(mu), on the same point set.
    for (size_t k = 0; k < environmentSamples_.size(); ++k) {
        const glm::dvec2 u = stratifiedPoint(int(k), int(environmentSamples_.size()));
        const Vec3 toward = sampleHenyeyGreenstein(viewDir, g, u.x, u.y);
        sum += add(toward, environment_->radiance(toward), environment_->pdf(toward));
    }
    return sum;
}

Rgb ReferenceRenderer::radiance(const Vec3& origin, const Vec3& dir, const ReferenceSettings& settings) const {
    // The camera ray stops at the first opaque blocker.
    double tStop = kInfinity;
    for (const auto& o : objects_) tStop = std::min(tStop, o.firstBlockerHit(origin, dir));
    const Rgb surface = settings.surface && scene_.render.surface
                            ? firstSurfaceReflection(objects_, lights_, origin, dir, tStop)
                            : Rgb(0.0);
    if (refracting_) return surface + refractedRadiance(origin, dir, settings);

    struct Segment {
        const VolumeObject* object;
        Interval span;
    };
    std::vector<Segment> segments;
    std::vector<Interval> inside;
    for (const auto& o : objects_) {
        // Whether the eye is inside, asked once per ray, lets a ray that grazes an
        // edge keep its parity (core/mesh_raycaster.cpp).
        o.boundary().insideIntervals(origin, dir, tStop, inside, o.boundary().contains(origin));
        for (const Interval& s : inside) segments.push_back({&o, s});
    }
    std::sort(segments.begin(), segments.end(),
              [](const Segment& a, const Segment& b) { return a.span.t0 < b.span.t0; });

    // Optical depth from the camera accumulates segment by segment, per channel.
    Rgb tauBefore(0.0);
    Rgb total(0.0);
    for (const Segment& seg : segments) {
        const VolumeObject& o = *seg.object;
        const Vec3 entry = origin + seg.span.t0 * dir;
        const Rgb sigmaT = o.desc().medium.sigmaT;
        auto integrand = [&](double t) -> Rgb {
            const Vec3 x = origin + t * dir;
            const Rgb tau = tauBefore + sigmaT * o.density().integrate(entry, x);
            return glm::exp(-tau) * inScattered(o, x, dir);
        };
        const double sigmaMax = std::max({sigmaT.r, sigmaT.g, sigmaT.b}) * o.density().maximum();
        if (seg.span.t1 > seg.span.t0)
            total += integrateIntoDenseMedium(integrand, seg.span.t0, seg.span.t1, sigmaMax, settings.tolerance);
        tauBefore += sigmaT * o.density().integrate(entry, origin + seg.span.t1 * dir);
    }
    // The environment behind, seen through every object on the way.
    if (environment_ && scene_.render.background && tStop == kInfinity)
        total += environment_->radiance(dir) * glm::exp(-tauBefore);
    return total + surface;
}

Image ReferenceRenderer::render(const ReferenceSettings& settings) const {
    // Embree casts rays in single precision: a boundary is known to about 1e-7 of
    // the coordinates' size, and an optical depth across that error must stay small.
    for (const VolumeObject& o : objects_) {
        const Bounds3 b = o.mesh().bounds();
        const double size = std::max({b.diagonal(), glm::length(b.min), glm::length(b.max)});
        const Rgb& sigmaT = o.desc().medium.sigmaT;
        const double depth = std::max({sigmaT.r, sigmaT.g, sigmaT.b}) * o.density().maximum() * size;
        if (depth > kMaxResolvedOpticalSize) {
            char text[160];
            std::snprintf(text, sizeof text,
                          "--method reference: sigma_t times the object's size reaches %.3g, beyond the %.0e its "
                          "single-precision ray casting resolves (docs/robustness.md)",
                          depth, kMaxResolvedOpticalSize);
            throw Error(o.desc().mesh.string(), text);
        }
    }
    const Camera& cam = scene_.camera;
    const CameraRays rays(cam);
    Image image(cam.width, cam.height);
    Progress progress("reference render", size_t(cam.height));
    tbb::task_arena arena(settings.threads > 0 ? settings.threads : tbb::task_arena::automatic);
    arena.execute([&] {
        tbb::parallel_for(tbb::blocked_range<int>(0, cam.height, 1), [&](const tbb::blocked_range<int>& rows) {
            for (int y = rows.begin(); y < rows.end(); ++y) {
                for (int x = 0; x < cam.width && settings.rows.owns(y); ++x) {
                    const Rgb L = radiance(rays.origin(), rays.direction(x + 0.5, y + 0.5), settings);
                    image.at(x, y) = glm::vec3(L);
                }
                progress.advance();
            }
        });
    });
    return image;
}

}  // namespace lucent
