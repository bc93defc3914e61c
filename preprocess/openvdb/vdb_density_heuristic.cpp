// The density heuristic's grids (preprocess/density_heuristic.h) on OpenVDB:
// T and the receivable light on every voxel of the distance field's band.
#include "preprocess/openvdb/vdb_density_heuristic.h"

#include <algorithm>
#include <array>
#include <span>

#include <openvdb/tools/GridOperators.h>
#include <openvdb/tools/Interpolation.h>
#include <openvdb/tree/LeafManager.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "core/progress.h"
#include "core/rng.h"
#include "core/sphere_directions.h"
#include "preprocess/openvdb/vdb_distance_field.h"

namespace lucent {

namespace {

class VdbHeuristicField final : public HeuristicField {
public:
    VdbHeuristicField(const VolumeObject& object, const VdbDistanceField& distance, const HeuristicSettings& settings);
    std::vector<HeuristicPoint> densityAtPoints(const std::vector<Vec3>& points,
                                                const HeuristicSettings& settings) const override;
    Vec3 firstMomentAt(const Vec3& point) const override;

private:
    openvdb::Vec3d gridPoint(const Vec3& world) const {
        const Vec3 q = (world - centre_) / scale_;
        return {q.x, q.y, q.z};
    }
    openvdb::Vec3SGrid::Ptr firstMoment_;  // T
    openvdb::FloatGrid::Ptr receivable_;   // integral exp(-tau) dw / (4 pi), in [0, 1]
    Vec3 centre_;                          // the grids' coordinates are relative to it,
    double scale_;                         // and divided by this (DistanceField::scale)
};

VdbHeuristicField::VdbHeuristicField(const VolumeObject& object, const VdbDistanceField& distance,
                                     const HeuristicSettings& settings)
    : centre_(distance.centre()), scale_(distance.scale()) {
    firstMoment_ = openvdb::Vec3SGrid::create(openvdb::Vec3s(0.0f));
    firstMoment_->setTransform(distance.grid().transform().copy());
    firstMoment_->topologyUnion(distance.grid());
    receivable_ = openvdb::FloatGrid::create(0.0f);
    receivable_->setTransform(distance.grid().transform().copy());
    receivable_->topologyUnion(distance.grid());

    std::vector<Vec3> dirs = fibonacciSphere(settings.directions);
    Rng rng(settings.seed, 0x4845);
    const glm::dmat3 rotation = randomRotation(rng);
    for (Vec3& w : dirs) w = rotation * w;
    const double weight = 4.0 * kPi / settings.directions;

    openvdb::tree::LeafManager<openvdb::Vec3STree> moments(firstMoment_->tree());
    openvdb::tree::LeafManager<openvdb::FloatTree> receivable(receivable_->tree());
    const auto& transform = firstMoment_->transform();
    Progress progress("density heuristic", moments.leafCount());
    // Leaves are visited in a fixed order and every voxel's value depends only on its
    // position, so the result is the same for any number of threads.
    // A leaf's voxels are neighbours: their rays of one direction go to Embree
    // as packets (MeshRaycaster::kPacket), side by side.
    constexpr size_t P = MeshRaycaster::kPacket;
    tbb::parallel_for(tbb::blocked_range<size_t>(0, moments.leafCount(), 1), [&](const tbb::blocked_range<size_t>& r) {
        std::vector<Vec3> points;
        std::vector<openvdb::Index> offsets;
        std::array<Vec3, P> origins, sameDirection;
        std::array<double, P> paths;
        std::array<Vec3, P> moment;
        std::array<double, P> zeroth;
        for (size_t l = r.begin(); l < r.end(); ++l) {
            auto& leafT = moments.leaf(l);
            auto* leafS = receivable.leaf(l).buffer().data();
            points.clear();
            offsets.clear();
            for (auto it = leafT.beginValueOn(); it; ++it) {
                const openvdb::Vec3d p = transform.indexToWorld(it.getCoord());
                points.push_back(centre_ + scale_ * Vec3(p.x(), p.y(), p.z()));
                offsets.push_back(it.pos());
            }
            for (size_t first = 0; first < points.size(); first += P) {
                const size_t count = std::min(P, points.size() - first);
                std::copy_n(points.begin() + first, count, origins.begin());
                moment.fill(Vec3(0.0));
                zeroth.fill(0.0);
                for (const Vec3& w : dirs) {
                    sameDirection.fill(w);
                    object.densityPaths(std::span(origins.data(), count), std::span(sameDirection.data(), count), false,
                                        std::span(paths.data(), count));
                    for (size_t k = 0; k < count; ++k) {
                        const double f = paths[k] == kInfinity ? 0.0 : std::exp(-settings.extinction * paths[k]);
                        moment[k] += f * w;
                        zeroth[k] += f;
                    }
                }
                for (size_t k = 0; k < count; ++k) {
                    leafT.setValueOnly(offsets[first + k],
                                       openvdb::Vec3s(float(weight * moment[k].x), float(weight * moment[k].y),
                                                      float(weight * moment[k].z)));
                    leafS[offsets[first + k]] = float(weight * zeroth[k] / (4.0 * kPi));
                }
            }
            progress.advance();
        }
    });
    raysCast = uint64_t(firstMoment_->activeVoxelCount()) * dirs.size();
}

std::vector<HeuristicPoint> VdbHeuristicField::densityAtPoints(const std::vector<Vec3>& points,
                                                               const HeuristicSettings& settings) const {
    const openvdb::FloatGrid::Ptr divergence = openvdb::tools::divergence(*firstMoment_);
    const openvdb::tools::GridSampler<openvdb::FloatGrid, openvdb::tools::BoxSampler> div(*divergence);
    const openvdb::tools::GridSampler<openvdb::FloatGrid, openvdb::tools::BoxSampler> receivable(*receivable_);
    std::vector<HeuristicPoint> out(points.size());
    tbb::parallel_for(tbb::blocked_range<size_t>(0, points.size(), 1024), [&](const tbb::blocked_range<size_t>& r) {
        for (size_t i = r.begin(); i < r.end(); ++i) {
            const openvdb::Vec3d p = gridPoint(points[i]);
            // The grid's coordinates are world / scale, so its divergence is scale times the world's.
            out[i].density = std::abs(div.wsSample(p)) / scale_;
            out[i].receivable = receivable.wsSample(p);
            out[i].culled = out[i].receivable < settings.cullEpsilon;
        }
    });
    return out;
}

Vec3 VdbHeuristicField::firstMomentAt(const Vec3& point) const {
    const openvdb::tools::GridSampler<openvdb::Vec3SGrid, openvdb::tools::BoxSampler> s(*firstMoment_);
    const openvdb::Vec3s v = s.wsSample(gridPoint(point));
    return Vec3(v.x(), v.y(), v.z());
}

}  // namespace

std::unique_ptr<HeuristicField> sampleVdbFirstMoment(const VolumeObject& object, const DistanceField& field,
                                                     const HeuristicSettings& settings) {
    return std::make_unique<VdbHeuristicField>(object, static_cast<const VdbDistanceField&>(field), settings);
}

}  // namespace lucent
