#include "preprocess/preprocessor.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>

#include "core/error.h"
#include "preprocess/density_heuristic.h"
#include "preprocess/distance_field.h"
#include "preprocess/internal/sample_description.h"
#include "preprocess/poisson_disk.h"
#include "preprocess/sample_weights.h"
#include "preprocess/sh_projection.h"

namespace lucent {
namespace {

class Stopwatch {
public:
    double lap() {
        const auto now = std::chrono::steady_clock::now();
        const double s = std::chrono::duration<double>(now - last_).count();
        last_ = now;
        return s;
    }

private:
    std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

// E_2(x) = integral_0^1 exp(-x / mu) dmu, by Gauss-Legendre on a substitution that
// tames the endpoint behaviour (mu = s^2).
double exponentialIntegralE2(double x) {
    static const double nodes[8] = {0.0198550717512319, 0.1016667612931866, 0.2372337950418355, 0.4082826787521751,
                                    0.5917173212478249, 0.7627662049581645, 0.8983332387068134, 0.9801449282487681};
    static const double weights[8] = {0.0506142681451881, 0.1111905172266872, 0.1568533229389436, 0.1813418916891810,
                                      0.1813418916891810, 0.1568533229389436, 0.1111905172266872, 0.0506142681451881};
    double sum = 0.0;
    for (int i = 0; i < 8; ++i) {
        const double s = nodes[i], mu = s * s;
        sum += weights[i] * 2.0 * s * std::exp(-x / mu);
    }
    return sum;
}

// The median divergence of the points that are not culled (0 if all are).
double medianDensity(const std::vector<HeuristicPoint>& points) {
    std::vector<double> values;
    for (const auto& p : points)
        if (!p.culled) values.push_back(p.density);
    if (values.empty()) return 0.0;
    std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
    return values[values.size() / 2];
}

// Percentiles make the normalisation robust to a few extreme divergences.
std::pair<double, double> densityRange(const std::vector<HeuristicPoint>& points) {
    std::vector<double> values;
    for (const auto& p : points)
        if (!p.culled) values.push_back(p.density);
    if (values.empty()) return {0.0, 1.0};
    std::sort(values.begin(), values.end());
    const double lo = values[size_t(0.02 * double(values.size() - 1))];
    const double hi = values[size_t(0.98 * double(values.size() - 1))];
    return {lo, hi > lo ? hi : lo + 1.0};
}

}  // namespace

double negligibleLightDepth(double extinction, double epsilon) {
    if (!(extinction > 0.0)) return kInfinity;
    double lo = 0.0, hi = 1.0;
    while (0.5 * exponentialIntegralE2(hi) > epsilon && hi < 1e3) hi *= 2.0;
    for (int i = 0; i < 60; ++i) {
        const double mid = 0.5 * (lo + hi);
        (0.5 * exponentialIntegralE2(mid) > epsilon ? lo : hi) = mid;
    }
    return hi / extinction;
}

PreprocessSettings publishedScheme(PreprocessSettings s) {
    s.scheme = SampleScheme::Published;
    s.widthFactor = 1.0;
    return s;
}

PreprocessSettings qualityPreset(const std::string& name) {
    PreprocessSettings s;
    if (name == "draft") {
        s.samples = 8000;
        s.heuristicDirections = 32;
        s.projectionDirections = 128;
        s.shOrder = 4;
    } else if (name == "default") {
    } else if (name == "high") {
        s.samples = 120000;
        s.heuristicDirections = 128;
        s.projectionDirections = 512;
        s.shOrder = 8;
    } else {
        throw Error("unknown quality '" + name + "' (expected draft, default or high)");
    }
    return s;
}

namespace {

// Light depth, in mean Poisson radii, under which an object is optically thick.
// Chosen on the unit sphere at 40k samples, 128x128, when the thick form was
// the Lommel-Seeliger law under each pixel's face: at sigma_t 8 (13 radii) the
// samples gave 7.7% and that law 13.7%; at 16 (6.9 radii) 15.6% and 7.0%. The
// marched form that replaced it is 1.5% at sigma_t 8 (docs/accuracy.md,
// Optically thick objects); the threshold stays while ss's refraction and its
// cost per light rest on the samples.
constexpr double kOpticallyThickDepthInRadii = 10.0;

uint32_t channelsOf(const MediumDesc& medium) {
    return (medium.sigmaT.r == medium.sigmaT.g && medium.sigmaT.g == medium.sigmaT.b) ? 1 : 3;
}

// What every sample set of the object records, samples or not.
SampleSet emptySetFor(const VolumeObject& object, const PreprocessSettings& settings, double r) {
    SampleSet set;
    set.shOrder = uint32_t(settings.shOrder);
    set.channels = channelsOf(object.desc().medium);
    set.sceneFingerprint = object.desc().fingerprint;
    set.mesh = object.objectMesh();
    set.bounds = object.mesh().bounds();
    set.parameters.seed = settings.seed;
    set.parameters.meanRadius = float(r);
    set.parameters.cullEpsilon = float(settings.cullEpsilon);
    set.parameters.scheme = settings.scheme;
    return set;
}

// The offset layers under the surface (thesis 3.2.2) and the distance field they
// come from, which the heuristic and the weights' normalisation read again.
struct LayerStack {
    double spacing = 0.0;
    std::vector<double> depths;
    std::unique_ptr<DistanceField> distance;
    std::vector<OffsetLayer> layers;
    RadiusSurface surface;  // every layer's triangles in one mesh
};

// Layers from half a spacing under the surface (the published scheme: one
// spacing) down to the light depth. In media so dense that light dies within one
// spacing, the layers close up so that a few still see light.
LayerStack buildLayers(const VolumeObject& object, const PreprocessSettings& settings, double r, double maxDepth) {
    LayerStack stack;
    const double firstLayer = settings.scheme == SampleScheme::Published ? 1.0 : 0.5;
    stack.spacing = std::min(settings.layerSpacing * r, maxDepth / (firstLayer + 2.0));
    for (int k = 0; k < settings.maxLayers; ++k) {
        const double depth = (k + firstLayer) * stack.spacing;
        if (depth > maxDepth) break;
        stack.depths.push_back(depth);
    }
    // One distance field serves the layers and the heuristic. Its voxels are 1.5 r:
    // fine enough for marching cubes to follow the surface at the scale samples
    // resolve, and for central differences of T, which varies over a mean free path.
    stack.distance = DistanceField::create(object.mesh(), 1.5 * r,
                                           (stack.depths.empty() ? 0.0 : stack.depths.back()) + stack.spacing);
    stack.layers = stack.distance->offsetLayers(stack.depths);
    if (stack.layers.empty())
        throw Error(object.desc().mesh.string(), "object is too thin for a single offset layer at depth " +
                                                     std::to_string(firstLayer * stack.spacing));
    // The layers that exist: depths past the object's half thickness have none
    // (the count the sample file records and lucent info shows).
    std::fprintf(stderr, "lucent: %s: %zu offset layers (spacing %.4g, light depth %.4g)\n", object.desc().name.c_str(),
                 stack.layers.size(), stack.spacing, std::min(maxDepth, 1e300));
    for (const auto& layer : stack.layers) {
        const uint32_t base = uint32_t(stack.surface.positions.size());
        stack.surface.positions.insert(stack.surface.positions.end(), layer.surface.positions.begin(),
                                       layer.surface.positions.end());
        for (auto tri : layer.surface.triangles)
            stack.surface.triangles.push_back({tri[0] + base, tri[1] + base, tri[2] + base});
    }
    return stack;
}

// Radius between 2r (lowest density) and r/2 (highest), thesis 3.2.4, relative
// to r. The thesis maps the density's range linearly onto that of the radii, so
// that a nearly even density (a thin medium) still spans all of it, and its noise
// decides where samples go. Lucent puts samples in proportion to the density
// instead: radius ~ density^(-1/3), clamped to the same range.
std::vector<double> relativeRadii(const std::vector<HeuristicPoint>& density, SampleScheme scheme) {
    std::vector<double> relativeRadius(density.size());
    if (scheme == SampleScheme::Published) {
        const auto [rhoLo, rhoHi] = densityRange(density);
        for (size_t i = 0; i < density.size(); ++i) {
            const double rho =
                density[i].culled ? 0.0 : std::clamp((density[i].density - rhoLo) / (rhoHi - rhoLo), 0.0, 1.0);
            relativeRadius[i] = std::exp2(1.0 - 2.0 * rho);
        }
    } else {
        const double median = medianDensity(density);
        for (size_t i = 0; i < density.size(); ++i) {
            const double rho = density[i].culled || !(median > 0.0) ? 0.0 : std::max(density[i].density / median, 0.0);
            relativeRadius[i] = rho > 0.0 ? std::clamp(std::cbrt(1.0 / rho), 0.5, 2.0) : 2.0;
        }
    }
    return relativeRadius;
}

// The disks a pass at mean radius r leaves on the live layers, before any is
// thrown: 0.35 per r^2 of their area, each triangle's area counted at its own
// radius. Measured over the bundled models, nine CGAL meshes and the seven CAD
// solids at 4k to 90k samples, the constant lies between 0.33 and 0.47: 0.34 to
// 0.37 on most from 16k samples up, higher where a layer has much edge for its
// area (thin ribs).
double expectedDisks(const RadiusSurface& live, const std::vector<double>& relativeRadius, double r) {
    double area = 0.0;  // sum of triangle area / relative radius^2
    for (const auto& tri : live.triangles) {
        const Vec3& a = live.positions[tri[0]];
        double inverseSquares = 0.0;
        for (uint32_t v : tri) inverseSquares += 1.0 / (relativeRadius[v] * relativeRadius[v]);
        area += 0.5 * glm::length(glm::cross(live.positions[tri[1]] - a, live.positions[tri[2]] - a)) * inverseSquares /
                3.0;
    }
    return 0.35 * area / (r * r);
}

constexpr double kCountExponent = 2.5;

// Poisson disks on the live layers with their count fitted to the request: the
// count scales as r^-k with k between 2 (layers sparser than r) and 3, about 2.5
// where the layers lie half a radius apart. The first pass takes its radius from
// the count expected of the layers' area; it lands within the 8% a pass is held
// to for 85 of the 100 meshes and counts measured (the 20 meshes above at 5k to
// 80k samples; two passes were needed for 98 of them before). The misses have
// much edge for their area: letters, ribs, slots. A pass that misses measures k
// against the next one, then corrects. Updates r to the radius used.
std::vector<DiskSample> fitPoissonDisks(const std::string& name, RadiusSurface& live,
                                        const std::vector<double>& relativeRadius, double& r,
                                        const PreprocessSettings& settings, PreprocessTimings& t) {
    std::vector<DiskSample> disks;
    // A budget of 8x the samples asked for: a pass that reaches it is cut short
    // (its count still steers the radius up), and a final one that does is an error.
    const size_t budget = 8 * size_t(std::max(settings.samples, 1)) + 1000;
    auto sampleWith = [&](double radius) {
        live.radius.resize(relativeRadius.size());
        for (size_t i = 0; i < relativeRadius.size(); ++i) live.radius[i] = radius * relativeRadius[i];
        disks = poissonDiskSample(live, settings.seed, 0.2 * radius, budget);
        ++t.poissonPasses;
        return double(std::max<size_t>(disks.size(), 1));
    };
    const double target = std::max(settings.samples, 1);
    const double expected = expectedDisks(live, relativeRadius, r);
    if (expected > 0.0 && std::isfinite(expected)) r *= std::pow(expected / target, 1.0 / kCountExponent);
    double n0 = sampleWith(r);
    for (int iteration = 0; iteration < 3 && std::abs(n0 / target - 1.0) > 0.08; ++iteration) {
        const double r1 = r * std::pow(n0 / target, 1.0 / kCountExponent);
        const double n1 = sampleWith(r1);
        if (std::abs(n1 / target - 1.0) <= 0.08) {  // as close as a first pass is asked to be
            r = r1;
            break;
        }
        const double k = std::clamp(std::log(n1 / n0) / std::log(r / r1), 1.5, 3.5);
        r = r1 * std::pow(n1 / target, 1.0 / k);
        n0 = sampleWith(r);
    }
    if (disks.size() >= budget)
        throw Error(name, "Poisson-disk sampling placed " + std::to_string(budget) + " samples, 8x the " +
                              std::to_string(settings.samples) +
                              " asked for, and stopped: the offset layers hold far "
                              "more area than the object's volume suggests (ask for fewer samples or check the mesh)");
    return disks;
}

// Partition-of-unity weights: thesis eq. 3.3 normalised (preprocess/sample_weights.h).
// The Galerkin weights leave the sum of the Gaussians a few per cent off on
// average (measured +4% on the sphere). Where every layer was sampled, the
// weighted Gaussians must hold exactly the volume they fill: the object minus
// its blockers, down to half a spacing under the deepest layer.
void applyWeights(const VolumeObject& object, const std::vector<WeightedSample>& weighted, const LayerStack& stack,
                  double shell, bool nothingCulled, const PreprocessSettings& settings, SampleSet& set) {
    const bool published = settings.scheme == SampleScheme::Published;
    const std::vector<float> weights =
        published ? volumeShareWeights(set.widths, shell) : partitionOfUnityWeights(weighted);
    double scale = 1.0;
    if (!published && nothingCulled && !weights.empty()) {
        double sampledVolume = std::abs(object.mesh().signedVolume());
        for (const TriangleMesh& blocker : object.blockerMeshes()) sampledVolume -= std::abs(blocker.signedVolume());
        const std::vector<OffsetLayer> floor =
            stack.distance->offsetLayers({stack.depths.back() + 0.5 * stack.spacing});
        if (!floor.empty()) sampledVolume -= std::abs(floor.front().surface.signedVolume());
        // What each weighted Gaussian and its image hold inside the region: all of
        // one Gaussian near a single boundary, less where the far side clips them.
        double held = 0.0;
        for (size_t i = 0; i < weights.size(); ++i) {
            held +=
                weights[i] * heldInside(weighted[i]) * std::pow(2.0 * kPi * double(set.widths[i]) * set.widths[i], 1.5);
        }
        if (sampledVolume > 0.0 && held > 0.0) scale = sampledVolume / held;
    }
    for (size_t i = 0; i < weights.size(); ++i) set.weights[i] = float(scale * weights[i]);
}

// Thesis Algorithms 1 and 2: layers, heuristic, Poisson disks, SH projection,
// for an object that is not placed.
SampleSet preprocessOwnSpace(const VolumeObject& object, const PreprocessSettings& settings, PreprocessTimings& t) {
    Stopwatch clock;
    const MediumDesc& medium = object.desc().medium;
    const TriangleMesh& mesh = object.mesh();
    if (settings.shOrder < 1 || settings.shOrder > int(kMaxSampleShOrder))
        throw Error("SH order " + std::to_string(settings.shOrder) + " is out of range (1 to " +
                    std::to_string(kMaxSampleShOrder) + ")");

    // The most penetrating channel decides how deep light reaches and what is culled.
    const double minSigmaT = std::min({medium.sigmaT.r, medium.sigmaT.g, medium.sigmaT.b});
    const double maxDepth = negligibleLightDepth(minSigmaT * object.density().minimum(), settings.cullEpsilon);

    // Mean radius r from the sample count: a maximal Poisson-disk set with spacing r
    // fills space at about 0.73 / r^3 (random sequential packing at 38% of spheres
    // of diameter r), over the shell that light reaches.
    const double shell = std::min(std::abs(mesh.signedVolume()), mesh.area() * maxDepth);
    double r = std::cbrt(0.726 * shell / std::max(settings.samples, 1));

    // Light that dies within a fraction of the samples' spacing leaves nothing for
    // Gaussians of that width to resolve: their mass sits mostly where no light is.
    // There the runtime marches each pixel's ray through the lit sliver instead
    // (runtime/internal/optically_thick.frag); the object needs no samples.
    if (settings.scheme == SampleScheme::Lucent && maxDepth < kOpticallyThickDepthInRadii * r) {
        std::fprintf(stderr,
                     "lucent: %s: light dies within %.3g, under %.3g sample spacings: optically thick, "
                     "each pixel's ray marched instead (no samples)\n",
                     object.desc().name.c_str(), maxDepth, maxDepth / r);
        SampleSet set = emptySetFor(object, settings, r);
        set.parameters.scheme = SampleScheme::OpticallyThick;
        t.layers = clock.lap();
        return set;
    }

    const LayerStack stack = buildLayers(object, settings, r, maxDepth);
    t.layerCount = stack.layers.size();
    t.layerVertices = stack.surface.positions.size();
    t.layers = clock.lap();

    // Density heuristic (thesis 3.2.3), read at every layer vertex.
    HeuristicSettings heuristic;
    heuristic.directions = settings.heuristicDirections;
    heuristic.extinction = minSigmaT;
    heuristic.cullEpsilon = settings.cullEpsilon;
    heuristic.seed = settings.seed;
    const std::unique_ptr<HeuristicField> heuristicField = sampleFirstMoment(object, *stack.distance, heuristic);
    t.heuristicRays = heuristicField->raysCast;
    t.firstMoments = clock.lap();
    const std::vector<HeuristicPoint> density = heuristicField->densityAtPoints(stack.surface.positions, heuristic);
    t.divergence = clock.lap();

    const std::vector<double> relativeRadius = relativeRadii(density, settings.scheme);
    RadiusSurface live;
    live.positions = stack.surface.positions;
    for (const auto& tri : stack.surface.triangles)
        if (!density[tri[0]].culled || !density[tri[1]].culled || !density[tri[2]].culled)
            live.triangles.push_back(tri);
    const bool nothingCulled = live.triangles.size() == stack.surface.triangles.size();
    if (live.triangles.empty())
        throw Error(object.desc().mesh.string(), "no point inside receives light above the cull threshold");
    const std::vector<DiskSample> disks =
        fitPoissonDisks(object.desc().mesh.string(), live, relativeRadius, r, settings, t);
    t.poissonDisk = clock.lap();

    SampleSet set = emptySetFor(object, settings, r);
    SampleParameters& p = set.parameters;
    p.heuristicDirections = uint32_t(settings.heuristicDirections);
    p.projectionDirections = uint32_t(settings.projectionDirections);
    p.layerCount = uint32_t(stack.layers.size());
    p.layerSpacing = float(stack.spacing);
    p.widthFactor = float(settings.widthFactor);
    const DescribedSamples described = describeSamples(object, disks, settings, set);
    applyWeights(object, described.weighted, stack, shell, nothingCulled, settings, set);

    // SH projection of each sample's attenuation (thesis 3.3.1).
    ProjectionSettings projection;
    projection.order = settings.shOrder;
    projection.directions = settings.projectionDirections;
    projection.seed = settings.seed;
    projection.shadowBlockersAtRuntime = settings.scheme != SampleScheme::Published;
    ProjectionResult projected =
        projectAttenuation(object, described.positions, set.boundary, projection, int(set.channels));
    set.sh = std::move(projected.coefficients);
    set.truncationError = std::move(projected.truncationError);
    set.boundary = std::move(projected.balls);
    t.projectionRays = projected.raysCast;
    t.projection = clock.lap();
    return set;
}

}  // namespace

SampleSet preprocessObject(const VolumeObject& object, const PreprocessSettings& settings, PreprocessTimings* timings) {
    PreprocessTimings local;
    PreprocessTimings& t = timings ? *timings : local;
    if (!object.placed()) return preprocessOwnSpace(object, settings, t);
    // Placed at scale s0, the object is optically its own mesh with sigma_t s0
    // per own unit: sampled so, every decision (layer depth, sample spacing
    // against the mean free path, optically thick or not) holds at the size it
    // is drawn at. Rotation and translation change nothing of it.
    const double s0 = object.placement().scale;
    ObjectDesc own = object.desc();
    own.transform = Similarity{};
    own.medium.sigmaT *= s0;
    const VolumeObject ownObject(own, object.objectMesh(), object.objectBlockerMeshes());
    SampleSet set = preprocessOwnSpace(ownObject, settings, t);
    // The stored coefficients stay per world unit, as the runtime reads them
    // (docs/sample-file.md, "Placement scale").
    for (glm::vec3& v : set.extinction) v /= float(s0);
    set.parameters.placementScale = float(s0);
    return set;
}

}  // namespace lucent
