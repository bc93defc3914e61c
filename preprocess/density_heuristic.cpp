#include "preprocess/density_heuristic.h"

#include <openvdb/tools/GridOperators.h>
#include <openvdb/tools/Interpolation.h>
#include <openvdb/tree/LeafManager.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "core/progress.h"
#include "core/rng.h"
#include "core/sphere_directions.h"

namespace lucent {

HeuristicField sampleFirstMoment(const VolumeObject& object, const DistanceField& distance,
                                 const HeuristicSettings& settings) {
    HeuristicField field;
    field.centre = distance.centre();
    field.scale = distance.scale();
    field.firstMoment = openvdb::Vec3SGrid::create(openvdb::Vec3s(0.0f));
    field.firstMoment->setTransform(distance.grid().transform().copy());
    field.firstMoment->topologyUnion(distance.grid());
    field.receivable = openvdb::FloatGrid::create(0.0f);
    field.receivable->setTransform(distance.grid().transform().copy());
    field.receivable->topologyUnion(distance.grid());

    std::vector<Vec3> dirs = fibonacciSphere(settings.directions);
    Rng rng(settings.seed, 0x4845);
    const glm::dmat3 rotation = randomRotation(rng);
    for (Vec3& w : dirs) w = rotation * w;
    const double weight = 4.0 * kPi / settings.directions;

    openvdb::tree::LeafManager<openvdb::Vec3STree> moments(field.firstMoment->tree());
    openvdb::tree::LeafManager<openvdb::FloatTree> receivable(field.receivable->tree());
    const auto& transform = field.firstMoment->transform();
    Progress progress("density heuristic", moments.leafCount());
    // Leaves are visited in a fixed order and every voxel's value depends only on its
    // position, so the result is the same for any number of threads.
    tbb::parallel_for(tbb::blocked_range<size_t>(0, moments.leafCount(), 1), [&](const tbb::blocked_range<size_t>& r) {
        for (size_t l = r.begin(); l < r.end(); ++l) {
            auto& leafT = moments.leaf(l);
            auto* leafS = receivable.leaf(l).buffer().data();
            for (auto it = leafT.beginValueOn(); it; ++it) {
                const openvdb::Vec3d p = transform.indexToWorld(it.getCoord());
                const Vec3 x = field.centre + field.scale * Vec3(p.x(), p.y(), p.z());
                Vec3 moment(0.0);
                double zeroth = 0.0;
                for (const Vec3& w : dirs) {
                    const double path = object.densityPath(x, w);
                    const double f = path == kInfinity ? 0.0 : std::exp(-settings.extinction * path);
                    moment += f * w;
                    zeroth += f;
                }
                it.setValue(openvdb::Vec3s(float(weight * moment.x), float(weight * moment.y), float(weight * moment.z)));
                leafS[it.pos()] = float(weight * zeroth / (4.0 * kPi));
            }
            progress.advance();
        }
    });
    field.raysCast = uint64_t(field.firstMoment->activeVoxelCount()) * dirs.size();
    return field;
}

std::vector<HeuristicPoint> densityAtPoints(HeuristicField& field, const std::vector<Vec3>& points,
                                            const HeuristicSettings& settings) {
    field.divergence = openvdb::tools::divergence(*field.firstMoment);
    const openvdb::tools::GridSampler<openvdb::FloatGrid, openvdb::tools::BoxSampler> div(*field.divergence);
    const openvdb::tools::GridSampler<openvdb::FloatGrid, openvdb::tools::BoxSampler> receivable(*field.receivable);
    std::vector<HeuristicPoint> out(points.size());
    tbb::parallel_for(tbb::blocked_range<size_t>(0, points.size(), 1024), [&](const tbb::blocked_range<size_t>& r) {
        for (size_t i = r.begin(); i < r.end(); ++i) {
            const Vec3 q = (points[i] - field.centre) / field.scale;
            const openvdb::Vec3d p(q.x, q.y, q.z);
            // The grid's coordinates are world / scale, so its divergence is scale times the world's.
            out[i].density = std::abs(div.wsSample(p)) / field.scale;
            out[i].receivable = receivable.wsSample(p);
            out[i].culled = out[i].receivable < settings.cullEpsilon;
        }
    });
    return out;
}

}  // namespace lucent
