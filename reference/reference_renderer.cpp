#include "reference/reference_renderer.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cstdio>

#include "core/error.h"

#include "core/camera_rays.h"
#include "core/progress.h"
#include "reference/light_arrival.h"
#include "reference/surface_reflection.h"

namespace lucent {
namespace {

double magnitude(const Rgb& c) { return std::max({std::abs(c.r), std::abs(c.g), std::abs(c.b)}); }

// Adaptive Simpson on [a, b] given f at a, midpoint and b, to absolute tolerance tol.
template <class F>
Rgb adaptiveSimpson(const F& f, double a, double b, const Rgb& fa, const Rgb& fm, const Rgb& fb, const Rgb& whole,
                    double tol, int depth) {
    const double m = 0.5 * (a + b);
    const Rgb flm = f(0.5 * (a + m)), frm = f(0.5 * (m + b));
    const Rgb left = (m - a) / 6.0 * (fa + 4.0 * flm + fm);
    const Rgb right = (b - m) / 6.0 * (fm + 4.0 * frm + fb);
    const Rgb delta = left + right - whole;
    if (depth <= 0 || magnitude(delta) <= 15.0 * tol) return left + right + delta / 15.0;  // Richardson step
    return adaptiveSimpson(f, a, m, fa, flm, fm, left, 0.5 * tol, depth - 1) +
           adaptiveSimpson(f, m, b, fm, frm, fb, right, 0.5 * tol, depth - 1);
}

// Integrates f over [a, b]: a fixed composite pass sizes the answer, then each
// panel is refined until its share of the tolerance is met.
template <class F>
Rgb integrate(const F& f, double a, double b, double relativeTolerance, double absoluteFloor = 1e-300) {
    constexpr int kPanels = 8;
    const double h = (b - a) / kPanels;
    Rgb values[2 * kPanels + 1];
    for (int i = 0; i <= 2 * kPanels; ++i) values[i] = f(a + 0.5 * h * i);
    Rgb coarse(0.0);
    for (int p = 0; p < kPanels; ++p) coarse += h / 6.0 * (values[2 * p] + 4.0 * values[2 * p + 1] + values[2 * p + 2]);
    const double tol = std::max(relativeTolerance * magnitude(coarse) / kPanels, absoluteFloor);
    Rgb total(0.0);
    for (int p = 0; p < kPanels; ++p) {
        const double x0 = a + h * p;
        const Rgb whole = h / 6.0 * (values[2 * p] + 4.0 * values[2 * p + 1] + values[2 * p + 2]);
        total += adaptiveSimpson(f, x0, x0 + h, values[2 * p], values[2 * p + 1], values[2 * p + 2], whole, tol, 24);
    }
    return total;
}

// Optical depth of a segment beyond which its integrand, falling like
// exp(-sigma_t (t - t0)) from the entry, is integrated in pieces.
constexpr double kOpticalDepthInOnePiece = 8.0;

// f over [a, b] when the medium can be optically deep there: fixed panels would
// step over the thin sliver where the light is scattered (and the integral would
// grow with sigma_t). So pieces from the entry, 1/sigma long and four times longer
// each, every one to the tolerance of what came before: about log4(sigma L) pieces.
template <class F>
Rgb integrateIntoDenseMedium(const F& f, double a, double b, double sigmaMax, double relativeTolerance) {
    if (!(sigmaMax * (b - a) > kOpticalDepthInOnePiece)) return integrate(f, a, b, relativeTolerance);
    Rgb total(0.0);
    double start = a, length = 1.0 / sigmaMax;
    while (start < b) {
        const double end = std::min(b, start + length);
        total += integrate(f, start, end, relativeTolerance, relativeTolerance * magnitude(total) / 64.0 + 1e-300);
        start = end;
        length *= 4.0;
    }
    return total;
}

}  // namespace

ReferenceRenderer::ReferenceRenderer(const SceneDesc& scene, const std::vector<VolumeObject>& objects)
    : scene_(scene), objects_(objects) {}

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
    Rgb sum(0.0);
    for (const Light& light : scene_.lights) {
        const std::optional<LightArrival> a = lightArrivingAt(light, x);
        if (!a) continue;
        // Phase function between the light's propagation direction (-toLight) and the
        // view's propagation direction (-viewDir).
        const double phase = henyeyGreenstein(glm::dot(a->toLight, viewDir), object.desc().medium.g);
        sum += phase * a->irradiance * transmittanceToLight(objects_, x, *a);
    }
    return sigmaS * sum;
}

Rgb ReferenceRenderer::radiance(const Vec3& origin, const Vec3& dir, const ReferenceSettings& settings) const {
    // The camera ray stops at the first opaque blocker.
    double tStop = kInfinity;
    for (const auto& o : objects_) tStop = std::min(tStop, o.firstBlockerHit(origin, dir));

    struct Segment {
        const VolumeObject* object;
        Interval span;
    };
    std::vector<Segment> segments;
    std::vector<Interval> inside;
    Rgb surface(0.0);
    double nearestSurface = kInfinity;
    std::vector<Crossing> cs;
    for (const auto& o : objects_) {
        // Whether the eye is inside, asked once per ray, lets a ray that grazes an
        // edge keep its parity (core/mesh_raycaster.cpp).
        o.boundary().insideIntervals(origin, dir, tStop, inside, o.boundary().contains(origin));
        for (const Interval& s : inside) segments.push_back({&o, s});
        if (settings.surface && scene_.render.surface && o.desc().surface) {
            o.boundary().crossings(origin, dir, cs);
            if (!cs.empty() && !cs.front().exits && cs.front().t < std::min(nearestSurface, tStop)) {
                nearestSurface = cs.front().t;
                const Vec3 hit = origin + cs.front().t * dir;
                surface = phongSurfaceReflection(*o.desc().surface, scene_.lights, hit,
                                                 o.shadingNormal(cs.front().face, hit), dir);
            }
        }
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
                for (int x = 0; x < cam.width; ++x) {
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
