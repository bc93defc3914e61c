#include "preprocess/internal/sample_description.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <optional>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace lucent {
namespace {

// p's boundary ball (SampleSet::boundary): tangent to the object's outer boundary
// at its nearest point, with the surface's mean curvature there (0 where it is
// concave). Blockers and density slabs are left out, since light leaves the object
// only through its boundary. The curvature comes from how the direction to the
// nearest point turns as a probe at depth D moves sideways: by 1 / (R - D) per
// unit on a sphere. Steps of a few triangles see the curvature of the tessellated
// surface, not the flatness of one triangle, but stay well inside the large faces
// of a box. The probe sits at least one step deep, under p when p is shallower:
// a sideways step from just under a convex surface would leave the object.
// nearest is the boundary's point nearest p; it bounds the probes' distances,
// which speeds their searches.
BoundaryBall boundaryBall(const VolumeObject& object, const Vec3& p, const Vec3& nearest, double curvatureStep) {
    const MeshRaycaster& boundary = object.boundary();
    auto towardSurface = [&](const Vec3& x, double& distance) {
        const Vec3 offset = boundary.closestPoint(x, glm::length(nearest - x)) - x;
        distance = glm::length(offset);
        return distance > 0.0 ? offset / distance : Vec3(0.0);
    };
    const Vec3 offset = nearest - p;
    const double depth = glm::length(offset);
    const Vec3 n = depth > 0.0 ? offset / depth : Vec3(0.0);
    BoundaryBall ball;
    if (!(depth > 0.0)) return ball;
    ball.normal = glm::vec3(n);
    ball.depth = float(depth);
    const Vec3 t1 = glm::normalize(std::abs(n.x) < 0.9 ? glm::cross(n, Vec3(1, 0, 0)) : glm::cross(n, Vec3(0, 1, 0)));
    const Vec3 t2 = glm::cross(n, t1);
    const double step = std::max(0.1 * depth, curvatureStep);
    const double probeDepth = std::max(depth, step);
    const Vec3 probe = p - (probeDepth - depth) * n;
    double turning = 0.0, unused = 0.0;
    for (const Vec3& t : {t1, t2}) turning += glm::dot(towardSurface(probe + step * t, unused) - n, t) / step;
    const double levelCurvature = std::max(0.5 * turning, 0.0);
    ball.curvature = float(levelCurvature / (1.0 + levelCurvature * probeDepth));
    return ball;
}

// Beyond this many Gaussian widths behind a sample, the far side of its region
// clips nothing the weights see (neighbours within 4 widths, their products
// narrower still).
constexpr double kThinReach = 8.0;
// Gaussians in a region less than kThinWidening Poisson radii across are widened
// by kThinWidening radius / thickness, up to kMostWidening times. Measured
// (docs/accuracy.md, Thin parts): a plate 1.2 radii thick went from 9.8% to
// 4.1% at 3 radii; 5.5 radii also brought a plate 3.9 radii thick from 5.9% to
// 3.5% for 0.3 points of CGAL's elephant (6.5 radii: 3.0% for 0.6 points).
constexpr double kThinWidening = 5.5;
constexpr double kMostWidening = 2.0;

// The region's extent across position, along the line from its nearest
// boundary point through it (a plate's thickness, a tube's diameter), or
// infinity when the far side lies more than reach behind position.
double regionThickness(const VolumeObject& object, const std::optional<DensitySlab>& slab, const Vec3& nearest,
                       const Vec3& position, double reach) {
    const Vec3 away = position - nearest;
    const double depth = glm::length(away);
    if (!(depth > 0.0)) return kInfinity;
    const Vec3 dir = away / depth;
    double behind = std::min(object.boundary().firstHit(position, dir), object.firstBlockerHit(position, dir));
    if (slab && dir[slab->axis] != 0.0) {
        const double plane = dir[slab->axis] > 0.0 ? slab->hi : slab->lo;
        behind = std::min(behind, (plane - position[slab->axis]) / dir[slab->axis]);
    }
    return behind > reach ? kInfinity : depth + behind;
}

}  // namespace

// Each disk outside the blockers becomes a sample: position, radius, Gaussian
// width, coefficients, its region and mirror image, its boundary ball.
DescribedSamples describeSamples(const VolumeObject& object, const std::vector<DiskSample>& disks,
                                 const PreprocessSettings& settings, SampleSet& set) {
    const bool published = settings.scheme == SampleScheme::Published;
    double edgeLength = 0.0;
    for (const auto& t : object.mesh().triangles)
        edgeLength += glm::length(object.mesh().positions[t[1]] - object.mesh().positions[t[0]]);
    edgeLength /= double(std::max<size_t>(object.mesh().triangles.size(), 1));
    const Vec3 extent = object.mesh().bounds().max - object.mesh().bounds().min;
    const double curvatureStep = std::min(2.0 * edgeLength, 0.25 * std::min({extent.x, extent.y, extent.z}));
    std::vector<DiskSample> kept;
    kept.reserve(disks.size());
    for (const auto& d : disks)
        if (!object.insideBlocker(d.position)) kept.push_back(d);
    const size_t n = kept.size(), base = set.positions.size();
    DescribedSamples described;
    described.positions.resize(n);
    described.weighted.resize(n);
    set.positions.resize(base + n);
    set.radii.resize(base + n);
    set.weights.resize(base + n);
    set.extinction.resize(base + n);
    set.widths.resize(base + n);
    set.region.resize(base + n);
    set.image.resize(base + n);
    set.boundary.resize(base + n);
    std::vector<int> slabAxis(n, -1);
    // Each sample on its own (closest points, rays across its region, its
    // boundary ball: four closest-point queries and a ray), so in parallel.
    tbb::parallel_for(tbb::blocked_range<size_t>(0, n, 64), [&](const tbb::blocked_range<size_t>& range) {
        for (size_t i = range.begin(); i != range.end(); ++i) {
            const DiskSample& d = kept[i];
            const size_t k = base + i;
            const Vec3 onBoundary = published ? d.position : object.boundary().closestPoint(d.position);
            described.positions[i] = d.position;
            set.positions[k] = glm::vec3(d.position);
            set.radii[k] = float(d.radius);
            // FWHM = widthFactor * radius (thesis 3.3.2); FWHM = 2 sqrt(2 ln 2) sigma.
            float width = float(settings.widthFactor * d.radius / (2.0 * std::sqrt(2.0 * std::log(2.0))));
            set.extinction[k] = glm::vec3(object.extinction(d.position));
            // The region a Gaussian is clipped to: the object minus its blockers, and its
            // density slab where the density jumps between slabs; its mirror image
            // across the region's nearest boundary (preprocess/sample_weights.h).
            glm::vec2 region(set.bounds.min.x, set.bounds.max.x);
            uint32_t regionKey = 0;
            Vec3 image = d.position;
            float thickness = HUGE_VALF;
            if (!published) {
                std::optional<DensitySlab> slab = object.density().slabAround(d.position);
                if (slab) {
                    slabAxis[i] = int(slab->axis);
                    region = glm::vec2(float(std::max(slab->lo, -1e30)), float(std::min(slab->hi, 1e30)));
                    regionKey = std::bit_cast<uint32_t>(region.x);  // one key per slab
                }
                const Vec3 nearest = object.closestRegionBoundary(d.position, onBoundary);
                image = 2.0 * nearest - d.position;
                const double across =
                    regionThickness(object, slab, nearest, d.position, kThinReach * kMostWidening * width);
                // A plate or a tube a few radii across holds few layers: a view ray
                // crosses the sum of the Gaussians at nearly one point of it, and its
                // ripple shows as grain. Wider Gaussians smooth it; the weights count
                // what the far side then clips (docs/accuracy.md, Thin parts).
                if (std::isfinite(across))
                    width *= float(std::clamp(kThinWidening * d.radius / across, 1.0, kMostWidening));
                const double behind = across - glm::length(d.position - nearest);
                thickness = behind > kThinReach * width ? HUGE_VALF : float(across);
            }
            set.widths[k] = width;
            set.region[k] = region;
            set.image[k] = glm::vec3(image);
            set.boundary[k] = published ? BoundaryBall{} : boundaryBall(object, d.position, onBoundary, curvatureStep);
            described.weighted[i] = {glm::vec3(d.position), glm::vec3(image), width, regionKey, thickness};
        }
    });
    for (int axis : slabAxis)
        if (axis >= 0) set.parameters.regionAxis = uint32_t(axis);
    return described;
}

}  // namespace lucent
