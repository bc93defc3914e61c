#include "reference/path_tracer.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <cmath>

#include "core/camera_rays.h"
#include "core/progress.h"
#include "reference/light_arrival.h"
#include "reference/quadrature.h"
#include "reference/reference_renderer.h"
#include "reference/path_channels.h"
#include "core/refraction.h"
#include "reference/surface_reflection.h"

namespace lucent {
namespace {

// The largest extinction the object's medium reaches in the channel: delta tracking's majorant.
double majorant(const VolumeObject& o, int channel) {
    return channelOf(o.desc().medium.sigmaT, channel) * o.density().maximum();
}

constexpr int kNoiseBatch = 16;

Rgb standardErrorOf(const Rgb& sum, const Rgb& sumSquares, int n) {
    const Rgb mean = sum / double(n);
    const Rgb variance = glm::max(sumSquares / double(n) - mean * mean, Rgb(0.0));
    return glm::sqrt(variance / double(std::max(n - 1, 1)));
}

// Every channel's error of the mean within target of it (a dark channel, mean 0, is done).
bool withinNoiseTarget(const Rgb& sum, const Rgb& sumSquares, int n, double target) {
    const Rgb error = standardErrorOf(sum, sumSquares, n), mean = sum / double(n);
    for (int c = 0; c < 3; ++c)
        if (error[c] > target * mean[c]) return false;
    return true;
}

}  // namespace

bool survivesRoulette(Rgb& throughput, PathSampler& rng) {
    const double keep = std::min(1.0, std::max({throughput.r, throughput.g, throughput.b}) / 0.01);
    if (rng.uniform() >= keep) return false;
    throughput /= keep;
    return true;
}

Vec3 sampleHenyeyGreenstein(const Vec3& dir, double g, double xi1, double xi2) {
    double cosTheta;
    if (std::abs(g) < 1e-4) {
        cosTheta = 1.0 - 2.0 * xi1;
    } else {
        // Inversion of the HG cumulative distribution of the angle to dir.
        const double s = (1.0 - g * g) / (1.0 - g + 2.0 * g * xi1);
        cosTheta = (1.0 + g * g - s * s) / (2.0 * g);
    }
    cosTheta = std::clamp(cosTheta, -1.0, 1.0);
    const double sinTheta = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
    const double phi = 2.0 * kPi * xi2;
    const Vec3 t1 =
        glm::normalize(std::abs(dir.x) < 0.9 ? glm::cross(dir, Vec3(1, 0, 0)) : glm::cross(dir, Vec3(0, 1, 0)));
    const Vec3 t2 = glm::cross(dir, t1);
    return glm::normalize(cosTheta * dir + sinTheta * (std::cos(phi) * t1 + std::sin(phi) * t2));
}

PathTracer::PathTracer(const SceneDesc& scene, const std::vector<VolumeObject>& objects,
                       const EnvironmentMap* environment)
    : scene_(scene),
      objects_(objects),
      environment_(environment),
      surfaceLights_(withEnvironmentLights(scene.lights, environment, kReferenceEnvironmentDirections)) {
    for (const VolumeObject& o : objects_) {
        const Rgb& s = o.desc().medium.sigmaT;
        grey_ = grey_ && s.r == s.g && s.g == s.b;
        refracting_ = refracting_ || o.desc().medium.ior != 1.0;
    }
}

double PathTracer::blockerDistance(const Vec3& origin, const Vec3& dir) const {
    double t = kInfinity;
    for (const VolumeObject& o : objects_) t = std::min(t, o.firstBlockerHit(origin, dir));
    return t;
}

std::optional<PathTracer::Collision> PathTracer::sampleCollision(const Vec3& origin, const Vec3& dir, double tMax,
                                                                 const VolumeObject* inside, PathSampler& rng,
                                                                 int channel) const {
    // Flights inside the scene's only object mostly end before its boundary:
    // the boundary is asked for only up to each tentative collision.
    const bool alone = tracksInside(inside);
    double tracked = 0.0;
    if (alone) {
        const InsideFlight flight = trackInside(*inside, origin, dir, tMax, rng, channel);
        if (flight.collision) return Collision{*flight.collision, inside};
        if (!flight.metBoundary) return std::nullopt;
        tracked = flight.reached;
    }
    thread_local std::vector<Span> spans;
    spansAlong(origin, dir, tMax, inside, spans);
    if (alone && !spans.empty() && spans.front().interval.t0 == 0.0) {
        // The span the flight started in was tracked up to `tracked`, past its end
        // unless single precision disagreed; what is left of it goes on from there
        // (a free flight forgets where it started).
        Interval& first = spans.front().interval;
        if (first.t1 <= tracked)
            spans.erase(spans.begin());
        else
            first.t0 = tracked;
    }
    return firstCollision(spans, origin, dir, rng, channel);
}

bool PathTracer::tracksInside(const VolumeObject* inside) const {
    return objects_.size() == 1 && inside == &objects_.front();
}

void PathTracer::spansAlong(const Vec3& origin, const Vec3& dir, double tMax, const VolumeObject* inside,
                            std::vector<Span>& spans) const {
    thread_local std::vector<Interval> intervals;
    spans.clear();
    for (const VolumeObject& o : objects_) {
        o.boundary().insideIntervals(origin, dir, tMax, intervals, &o == inside);
        for (const Interval& i : intervals) spans.push_back({i, &o});
    }
    std::sort(spans.begin(), spans.end(), [](const Span& a, const Span& b) { return a.interval.t0 < b.interval.t0; });
}

std::optional<PathTracer::Collision> PathTracer::firstCollision(const std::vector<Span>& spans, const Vec3& origin,
                                                                const Vec3& dir, PathSampler& rng, int channel) const {
    for (const Span& span : spans)
        if (const std::optional<double> t = sampleCollisionIn(*span.object, origin, dir, span.interval, rng, channel))
            return Collision{*t, span.object};
    return std::nullopt;
}

template <class PastEnd>
PathTracer::Tracked PathTracer::deltaTrack(const VolumeObject& o, const Vec3& origin, const Vec3& dir, double t0,
                                           const PastEnd& pastEnd, PathSampler& rng, int channel) {
    const double mu = majorant(o, channel);
    if (!(mu > 0.0)) return {std::nullopt, t0};
    const double sigmaT = channelOf(o.desc().medium.sigmaT, channel);
    // Tentative collisions at rate mu, each real with probability sigma(x) / mu.
    for (double t = t0, u = rng.flightUniform();; u = rng.uniform()) {
        t -= std::log(1.0 - u) / mu;
        if (pastEnd(t)) return {std::nullopt, t};
        const double sigma = sigmaT * o.density().at(origin + t * dir);
        if (rng.uniform() * mu < sigma) return {t, t};
    }
}

std::optional<double> PathTracer::sampleCollisionIn(const VolumeObject& o, const Vec3& origin, const Vec3& dir,
                                                    const Interval& span, PathSampler& rng, int channel) {
    const auto pastEnd = [&](double t) { return t >= span.t1; };
    return deltaTrack(o, origin, dir, span.t0, pastEnd, rng, channel).collision;
}

PathTracer::InsideFlight PathTracer::trackInside(const VolumeObject& o, const Vec3& origin, const Vec3& dir,
                                                 double tMax, PathSampler& rng, int channel) {
    // sampleCollisionIn over the span from origin to the boundary, drawing the
    // same numbers, with the boundary found lazily: a nearest-hit query up to each
    // tentative collision, where the span's end needs every crossing of the ray.
    // Each null collision costs one more such query, a short one: on the bunny at
    // a tenth and a hundredth of its majorant, handing over to the spans after
    // four of them did not change the time.
    bool metBoundary = false;
    const auto pastEnd = [&](double t) {
        metBoundary = o.boundary().firstCrossing(origin, dir, 0.0, std::min(t, tMax)).has_value();
        return metBoundary || t >= tMax;
    };
    const Tracked tracked = deltaTrack(o, origin, dir, 0.0, pastEnd, rng, channel);
    return {tracked.collision, tracked.reached, metBoundary};
}

Rgb PathTracer::gatherLights(const VolumeObject& object, const Vec3& x, const Vec3& dir, PathSampler& rng) const {
    Rgb sum = gatherSceneLights(object, x, dir, rng);
    if (environment_) sum += gatherEnvironment(object, x, dir, rng);
    return sum;
}

Rgb PathTracer::gatherSceneLights(const VolumeObject& object, const Vec3& x, const Vec3& dir, PathSampler& rng) const {
    Rgb sum(0.0);
    for (const Light& light : scene_.lights) {
        // A sphere light: one direction of its cone at random (only then: other scenes keep their random stream).
        double u = 0.5, v = 0.5;
        if (light.radius > 0.0) u = rng.uniform(), v = rng.uniform();
        const std::optional<LightArrival> a = lightArrivingAt(light, x, u, v);
        if (!a) continue;
        sum += henyeyGreenstein(glm::dot(a->toLight, dir), object.desc().medium.g) * a->irradiance *
               transmittanceToLight(objects_, x, *a);
    }
    return sum;
}

namespace {

// The power heuristic with exponent 2 (Veach 1997, 9.2.4).
double powerHeuristic(double pdf, double other) {
    const double a = pdf * pdf, b = other * other;
    return a + b > 0.0 ? a / (a + b) : 0.0;
}

}  // namespace

Rgb PathTracer::gatherEnvironment(const VolumeObject& object, const Vec3& x, const Vec3& dir, PathSampler& rng) const {
    const double u1 = rng.uniform(), u2 = rng.uniform();
    const EnvironmentMap::Sample s = environment_->sample(u1, u2);
    if (!(s.pdf > 0.0) || magnitude(s.radiance) == 0.0) return Rgb(0.0);
    const double phase = henyeyGreenstein(glm::dot(s.toward, dir), object.desc().medium.g);
    const LightArrival arrival{s.toward, kInfinity, s.radiance};
    // The phase function draws the same direction with density phase (sampleHenyeyGreenstein).
    return phase * s.radiance * transmittanceToLight(objects_, x, arrival) * (powerHeuristic(s.pdf, phase) / s.pdf);
}

Rgb PathTracer::escaped(const Vec3& previous, const Vec3& w, double g, bool scattered, bool weighed) const {
    if (!environment_ || (!scattered && !scene_.render.background)) return Rgb(0.0);
    const Rgb L = environment_->radiance(w);
    if (!scattered || !weighed) return L;
    // Drawn by the phase function around the previous direction: weighed against gatherEnvironment.
    return L * powerHeuristic(henyeyGreenstein(glm::dot(w, previous), g), environment_->pdf(w));
}

Rgb PathTracer::surfaceTerm(const Vec3& origin, const Vec3& dir, double tStop, const PathSettings& settings) const {
    // At the first front face before any blocker, as the reference adds it.
    if (!settings.surface || !scene_.render.surface) return Rgb(0.0);
    return firstSurfaceReflection(objects_, surfaceLights_, origin, dir, tStop);
}

PathTracer::CameraRay PathTracer::cameraRay(const Vec3& origin, const Vec3& dir, const PathSettings& settings) const {
    CameraRay ray;
    ray.origin = origin;
    ray.dir = dir;
    ray.tStop = blockerDistance(origin, dir);
    ray.surface = surfaceTerm(origin, dir, ray.tStop, settings);
    ray.inside = containing(origin);
    ray.spansKept = !tracksInside(ray.inside);
    if (ray.spansKept) spansAlong(origin, dir, ray.tStop, ray.inside, ray.spans);
    return ray;
}

const VolumeObject* PathTracer::containing(const Vec3& p) const {
    const VolumeObject* inside = nullptr;
    for (const VolumeObject& o : objects_)
        if (o.contains(p)) inside = &o;
    return inside;
}

Rgb PathTracer::radiance(const Vec3& origin, const Vec3& dir, PathSampler& rng, const PathSettings& settings,
                         int channel) const {
    if (refracting_) return refractedRadiance(origin, dir, rng, settings, channel);
    const CameraRay ray = cameraRay(origin, dir, settings);
    return masked(ray.surface, channel) + scattered(ray, rng, settings, channel);
}

Rgb PathTracer::scattered(const CameraRay& ray, PathSampler& rng, const PathSettings& settings, int channel) const {
    double tStop = ray.tStop;
    Rgb total(0.0);
    const VolumeObject* inside = ray.inside;
    Vec3 x = ray.origin, w = ray.dir, previous = ray.dir;
    Rgb throughput(1.0);
    for (int collisions = 0;; ++collisions) {
        const std::optional<Collision> c = collisions == 0 && ray.spansKept
                                               ? firstCollision(ray.spans, x, w, rng, channel)
                                               : sampleCollision(x, w, tStop, inside, rng, channel);
        if (!c) {
            if (tStop == kInfinity)
                total +=
                    throughput *
                    masked(escaped(previous, w, inside ? inside->desc().medium.g : 0.0, collisions > 0, true), channel);
            break;
        }
        if (collisions == settings.maxScatter) break;
        x += c->t * w;
        inside = c->object;
        // Free flights sampled in proportion to sigma_t T leave the albedo as the
        // weight of each collision (the collision estimator).
        throughput *= masked(inside->desc().medium.albedo, channel);
        total += throughput * masked(gatherLights(*inside, x, w, rng), channel);
        if (collisions >= 3 && !survivesRoulette(throughput, rng)) break;
        double xi1, xi2;
        rng.directionUniforms(xi1, xi2);
        previous = w;
        w = sampleHenyeyGreenstein(w, inside->desc().medium.g, xi1, xi2);
        tStop = blockerDistance(x, w);
    }
    return total;
}

PathTracer::Exit PathTracer::walk(const Vec3& origin, const Vec3& dir, PathSampler& rng, int maxScatter,
                                  int channel) const {
    if (refracting_) return refractedWalk(origin, dir, rng, maxScatter, channel);
    Exit exit;
    const VolumeObject* inside = containing(origin);
    Vec3 x = origin, w = dir;
    while (true) {
        const double tStop = blockerDistance(x, w);
        const std::optional<Collision> c = sampleCollision(x, w, tStop, inside, rng, channel);
        if (!c) {
            exit.escaped = tStop == kInfinity;
            exit.position = x;
            exit.direction = w;
            return exit;
        }
        if (exit.collisions == maxScatter) return exit;
        x += c->t * w;
        inside = c->object;
        exit.weight *= inside->desc().medium.albedo;
        ++exit.collisions;
        double xi1, xi2;
        rng.directionUniforms(xi1, xi2);
        w = sampleHenyeyGreenstein(w, inside->desc().medium.g, xi1, xi2);
    }
}

PathTracer::Result PathTracer::render(const PathSettings& settings) const {
    const Camera& cam = scene_.camera;
    const CameraRays rays(cam);
    Result result{Image(cam.width, cam.height), Image(cam.width, cam.height)};
    const int spp = std::max(settings.samplesPerPixel, 1);
    Progress progress("path tracing", size_t(cam.height));
    std::atomic<size_t> samplesTaken{0};
    tbb::task_arena arena(settings.threads > 0 ? settings.threads : tbb::task_arena::automatic);
    arena.execute([&] {
        tbb::parallel_for(tbb::blocked_range<int>(0, cam.height, 1), [&](const tbb::blocked_range<int>& range) {
            for (int y = range.begin(); y < range.end(); ++y) {
                for (int x = 0; x < cam.width && settings.rows.owns(y); ++x) {
                    // One stream per pixel: the image is the same for any thread count.
                    const uint64_t pixel = uint64_t(y) * uint64_t(cam.width) + uint64_t(x);
                    PathSampler rng = settings.stratified ? PathSampler(settings.seed, pixel)
                                                          : PathSampler(Rng(settings.seed, pixel));
                    const Vec3 dir = rays.direction(x + 0.5, y + 0.5);
                    // What every path of the pixel shares (its surface term, its
                    // camera ray's crossings) is found once for them all.
                    std::optional<CameraRay> ray;
                    if (!refracting_) ray = cameraRay(rays.origin(), dir, settings);
                    Rgb sum(0.0), sumSquares(0.0);
                    int taken = 0;
                    while (taken < spp) {
                        const int batch = settings.noiseTarget > 0.0 ? std::min(kNoiseBatch, spp - taken) : spp;
                        for (int s = 0; s < batch; ++s) {
                            rng.startPath(uint32_t(taken + s));
                            Rgb L = ray ? ray->surface : Rgb(0.0);
                            for (int channel = grey_ ? -1 : 0; channel < (grey_ ? 0 : 3); ++channel)
                                L += ray ? scattered(*ray, rng, settings, channel)
                                         : radiance(rays.origin(), dir, rng, settings, channel);
                            sum += L;
                            sumSquares += L * L;
                        }
                        taken += batch;
                        if (settings.noiseTarget > 0.0 && taken >= 2 * kNoiseBatch &&
                            withinNoiseTarget(sum, sumSquares, taken, settings.noiseTarget))
                            break;
                    }
                    const Rgb mean = sum / double(taken);
                    result.mean.at(x, y) = glm::vec3(mean);
                    result.standardError.at(x, y) = glm::vec3(standardErrorOf(sum, sumSquares, taken));
                    samplesTaken += size_t(taken);
                }
                progress.advance();
            }
        });
    });
    result.samplesTaken = samplesTaken;
    return result;
}

}  // namespace lucent
