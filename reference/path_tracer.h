#pragma once
// The ground truth for full light transport (--method path): a volumetric path
// tracer on Lucent's exact scene semantics. From every pixel centre (as the
// single-scattering reference) a camera path enters the media, collides where
// delta tracking against each object's majorant says (exact for constant
// density, unbiased for layers and grids), and at every collision gathers each
// light directly (next-event estimation: the transmittance to the light is the
// exact exp(-sigma_t path integral), through every object, zero through a
// blocker) before scattering by Henyey-Greenstein. An object whose ior is 1 has
// an index-matched boundary; any other reflects and refracts by Fresnel's
// equations, and the lights reach its inside through it (core/refraction.h,
// reference/refracted_paths.cpp). Blockers absorb. Paths end after maxScatter collisions (1: single scattering,
// which must agree with --method reference) or by Russian roulette.
//
// Media whose sigma_t differs between colour channels are traced once per
// channel, each path sampling that channel's extinction; grey media trace one
// path for all three.
#include <cstdint>
#include <optional>
#include <vector>

#include "core/environment_map.h"
#include "core/method.h"
#include "core/image.h"
#include "reference/path_sampler.h"
#include "core/scene.h"
#include "core/volume_object.h"
#include "core/refraction.h"

namespace lucent {

struct PathSettings {
    int samplesPerPixel = 64;  // with noiseTarget: the most a pixel may take
    // Relative standard error each pixel stops at (0: every pixel takes
    // samplesPerPixel). Pixels sample in batches of 16 until the error of their
    // mean, in every channel, is at most this share of it.
    double noiseTarget = 0.0;
    int maxScatter = 1 << 20;  // collisions gathered per path: 1 is single scattering
    uint64_t seed = 1;
    int threads = 0;      // 0: all cores
    bool surface = true;  // add the direct Phong surface term at the first front face
    // Each pixel's paths stratified in their first bounces (PathSampler);
    // false: independent paths (lucent-bench-path measures the difference).
    bool stratified = true;
    RowShare rows;  // the rows to render; the others stay 0
};

class PathTracer {
public:
    // environment: the scene's environment light, or none. Collisions sample it
    // and the phase function both, weighed by the power heuristic (multiple
    // importance sampling, Veach 1997 ch. 9); paths that leave the media see it.
    PathTracer(const SceneDesc& scene, const std::vector<VolumeObject>& objects,
               const EnvironmentMap* environment = nullptr);

    struct Result {
        Image mean;               // radiance per pixel
        Image standardError;      // of the mean, per pixel and channel
        size_t samplesTaken = 0;  // paths over all pixels
    };
    Result render(const PathSettings& settings) const;

    // One camera path's radiance estimate along a unit direction. channel < 0
    // traces all channels at once (grey media only), else that channel alone.
    Rgb radiance(const Vec3& origin, const Vec3& dir, PathSampler& rng, const PathSettings& settings,
                 int channel) const;

    // The analog random walk of one particle that starts at origin travelling
    // along dir, with no light gathered: where it leaves the media, for tallies
    // of reflectance and transmittance (the slab tests).
    struct Exit {
        bool escaped = false;  // false: absorbed by a blocker or stopped by maxScatter
        Vec3 position{0.0}, direction{0.0};
        Rgb weight{1.0};  // the product of the albedos met
        int collisions = 0;
    };
    Exit walk(const Vec3& origin, const Vec3& dir, PathSampler& rng, int maxScatter, int channel) const;

    // Whether every medium is grey (one path serves all three channels).
    bool grey() const { return grey_; }

private:
    struct Collision {
        double t;
        const VolumeObject* object;
    };
    // A stretch of a ray inside an object.
    struct Span {
        Interval interval;
        const VolumeObject* object;
    };
    // The stretches of origin + t dir, 0 <= t <= tMax, inside each object, in order
    // of their start: every crossing of the ray collected.
    void spansAlong(const Vec3& origin, const Vec3& dir, double tMax, const VolumeObject* inside,
                    std::vector<Span>& spans) const;
    // The first collision within the spans, each tracked in turn.
    std::optional<Collision> firstCollision(const std::vector<Span>& spans, const Vec3& origin, const Vec3& dir,
                                            PathSampler& rng, int channel) const;
    // Whether flights from inside go through trackInside(): inside is the scene's only object.
    bool tracksInside(const VolumeObject* inside) const;
    // What every path of a pixel shares, found once for them all (an index-matched
    // scene's camera ray): where a blocker stops it, its surface term, the object
    // the camera is in and, unless trackInside() takes the first flight, its spans.
    struct CameraRay {
        Vec3 origin, dir;
        double tStop = kInfinity;
        Rgb surface{0.0};
        const VolumeObject* inside = nullptr;
        bool spansKept = false;
        std::vector<Span> spans;
    };
    CameraRay cameraRay(const Vec3& origin, const Vec3& dir, const PathSettings& settings) const;
    // radiance() without the surface term, from a camera ray's shared part.
    Rgb scattered(const CameraRay& ray, PathSampler& rng, const PathSettings& settings, int channel) const;
    // The first collision along origin + t dir before tMax, or none. inside is the
    // object origin lies in (nullptr: none).
    std::optional<Collision> sampleCollision(const Vec3& origin, const Vec3& dir, double tMax,
                                             const VolumeObject* inside, PathSampler& rng, int channel) const;
    // The first real collision in o within span along origin + t dir, by delta tracking.
    static std::optional<double> sampleCollisionIn(const VolumeObject& o, const Vec3& origin, const Vec3& dir,
                                                   const Interval& span, PathSampler& rng, int channel);
    // A flight from inside o, the scene's only object, tracked until it collides
    // (collision), reaches tMax, or its tentative collision at `reached` lies past
    // the boundary (metBoundary): then the spans beyond take over.
    struct InsideFlight {
        std::optional<double> collision;
        double reached = 0.0;
        bool metBoundary = false;
    };
    static InsideFlight trackInside(const VolumeObject& o, const Vec3& origin, const Vec3& dir, double tMax,
                                    PathSampler& rng, int channel);
    // Delta tracking in o from t0 until a real collision, or until pastEnd(t) says
    // the tentative collision at t lies past the flight's end (then reached = t).
    struct Tracked {
        std::optional<double> collision;
        double reached = 0.0;
    };
    template <class PastEnd>
    static Tracked deltaTrack(const VolumeObject& o, const Vec3& origin, const Vec3& dir, double t0,
                              const PastEnd& pastEnd, PathSampler& rng, int channel);
    // The Phong surface term at the first front face before tStop, as the reference adds it.
    Rgb surfaceTerm(const Vec3& origin, const Vec3& dir, double tStop, const PathSettings& settings) const;
    // The object p lies in, or nullptr.
    const VolumeObject* containing(const Vec3& p) const;
    // radiance() and walk() in a scene with a refracting boundary (core/refraction.h):
    // paths go from boundary to boundary, reflected or refracted by Fresnel's odds there.
    Rgb refractedRadiance(const Vec3& origin, const Vec3& dir, PathSampler& rng, const PathSettings& settings,
                          int channel) const;
    Exit refractedWalk(const Vec3& origin, const Vec3& dir, PathSampler& rng, int maxScatter, int channel) const;
    // What a path at x going along w meets first in a refracting scene: a
    // collision in the object it is inside (collision), else the next boundary
    // (boundary, with the object it belongs to), else nothing or a blocker.
    struct Ahead {
        std::optional<double> collision;
        std::optional<BoundaryHit> boundary;
        const VolumeObject* object = nullptr;
        bool blocked = false;  // a blocker comes first: the path ends
    };
    Ahead ahead(const VolumeObject* inside, const Vec3& x, const Vec3& w, PathSampler& rng, int channel) const;
    // The light gathered at a collision in a refracting scene: through the boundary
    // for a refracting object, along straight lines for an index-matched one.
    Rgb gatherLightsRefracted(const VolumeObject& object, const Vec3& x, const Vec3& dir, PathSampler& rng) const;
    // Where the ray stops at an opaque blocker, or infinity.
    double blockerDistance(const Vec3& origin, const Vec3& dir) const;
    // sum_j p(w_j, dir) E_j T_j at x: the light arriving at x, scattered along dir.
    Rgb gatherLights(const VolumeObject& object, const Vec3& x, const Vec3& dir, PathSampler& rng) const;
    // gatherLights without the environment.
    Rgb gatherSceneLights(const VolumeObject& object, const Vec3& x, const Vec3& dir, PathSampler& rng) const;
    // The environment's share of the light at x scattered along dir, from one
    // direction drawn from the map, with its multiple importance weight.
    Rgb gatherEnvironment(const VolumeObject& object, const Vec3& x, const Vec3& dir, PathSampler& rng) const;
    // What a path that leaves every medium along w sees of the environment:
    // after a collision, with the weight that pairs it with gatherEnvironment;
    // straight from the camera, only with the scene's background on.
    Rgb escaped(const Vec3& previous, const Vec3& w, double g, bool scattered, bool weighed) const;

    const SceneDesc& scene_;
    const std::vector<VolumeObject>& objects_;
    const EnvironmentMap* environment_ = nullptr;
    std::vector<Light> surfaceLights_;  // the surface term's: the scene's and the environment's, as the reference's
    bool grey_ = true;
    bool refracting_ = false;  // some object's ior differs from 1
};

// Russian roulette, once a path has scattered a few times: false ends it; true
// keeps it and divides its throughput by the chance it had, so the estimate
// stays unbiased. The chance is 1 while the path's largest channel carries at
// least 1% of its light, in proportion below (as pbrt-v4 and Cycles, with a
// lower threshold): a medium that absorbs nothing ends no path (the white
// furnace stays exact), and PathSettings::maxScatter bounds the walk. Why not
// min(0.95, weight): in albedo 0.95 that ended 5% of the paths at every
// collision while their light was still large; on the wax bunny the variance
// per path fell from 1.14x Cycles' to 0.85x, for 1.15x the time a path.
bool survivesRoulette(Rgb& throughput, PathSampler& rng);

// A direction from the Henyey-Greenstein distribution with mean cosine g around
// the unit propagation direction dir (xi1, xi2 uniform in [0, 1)).
Vec3 sampleHenyeyGreenstein(const Vec3& dir, double g, double xi1, double xi2);

}  // namespace lucent
