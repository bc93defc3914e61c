#include "preprocess/density_heuristic.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "core/progress.h"
#include "core/rng.h"
#include "core/sphere_directions.h"

namespace lucent {

FirstMomentStencils sampleFirstMoments(const VolumeObject& object, const std::vector<Vec3>& points,
                                       const HeuristicSettings& settings) {
    FirstMomentStencils result;
    result.stencils.resize(points.size());
    const std::vector<Vec3> lattice = fibonacciSphere(settings.directions);
    const double weight = 4.0 * kPi / settings.directions;
    const Vec3 axes[3] = {Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
    Progress progress("density heuristic", points.size());
    tbb::parallel_for(tbb::blocked_range<size_t>(0, points.size(), 64), [&](const tbb::blocked_range<size_t>& range) {
        std::vector<Vec3> dirs(lattice.size());
        for (size_t i = range.begin(); i < range.end(); ++i) {
            auto& s = result.stencils[i];
            if (object.insideBlocker(points[i])) {
                s.blocked = true;
                continue;
            }
            // Stratified Monte Carlo: the lattice under a random rotation of this point's
            // own. All six neighbours share it, so the noise cancels in the differences.
            Rng rng(settings.seed, i);
            const glm::dmat3 rotation = randomRotation(rng);
            for (size_t k = 0; k < lattice.size(); ++k) dirs[k] = rotation * lattice[k];
            for (int n = 0; n < 6; ++n) {
                const Vec3 x = points[i] + (n % 2 == 0 ? 1.0 : -1.0) * settings.step * axes[n / 2];
                Vec3 moment(0.0);
                double zeroth = 0.0;
                for (const Vec3& w : dirs) {
                    const double path = object.densityPath(x, w);
                    const double f = path == kInfinity ? 0.0 : std::exp(-settings.extinction * path);
                    moment += f * w;
                    zeroth += f;
                }
                s.moment[n] = weight * moment;
                s.zeroth[n] = weight * zeroth;
            }
            progress.advance();
        }
    });
    result.raysCast = uint64_t(points.size()) * 6 * lattice.size();
    return result;
}

std::vector<HeuristicPoint> divergenceDensity(const FirstMomentStencils& moments, const HeuristicSettings& settings) {
    std::vector<HeuristicPoint> out(moments.stencils.size());
    for (size_t i = 0; i < out.size(); ++i) {
        const auto& s = moments.stencils[i];
        if (s.blocked) continue;
        // Central differences, thesis 3.2.3.
        const double div = (s.moment[0].x - s.moment[1].x + s.moment[2].y - s.moment[3].y + s.moment[4].z -
                            s.moment[5].z) / (2.0 * settings.step);
        double zeroth = 0.0;
        for (double z : s.zeroth) zeroth += z;
        out[i].density = std::abs(div);
        out[i].receivable = zeroth / 6.0 / (4.0 * kPi);
        out[i].culled = out[i].receivable < settings.cullEpsilon;
    }
    return out;
}

}  // namespace lucent
