#include "runtime/sample_weights.h"

#include "core/mesh_raycaster.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

namespace lucent {

namespace {
double normalCdf(double x) { return 0.5 * std::erfc(-x / std::sqrt(2.0)); }
}  // namespace

std::vector<float> partitionOfUnityWeights(const SampleSet& samples, const TriangleMesh& boundary, double cutoffSigmas) {
    const size_t n = samples.size();
    std::vector<float> weights(n, 1.0f);
    if (n == 0) return weights;
    // Depth of every centre under the boundary.
    const MeshRaycaster surface(boundary);
    std::vector<double> depth(n);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, n, 256), [&](const tbb::blocked_range<size_t>& r) {
        for (size_t i = r.begin(); i < r.end(); ++i) depth[i] = surface.distanceToSurface(Vec3(samples.positions[i]));
    });
    float maxWidth = 0.0f;
    Bounds3 box;
    for (size_t i = 0; i < n; ++i) {
        maxWidth = std::max(maxWidth, samples.widths[i]);
        box.extend(Vec3(samples.positions[i]));
    }
    // Bin centres into cells as wide as the largest reach.
    const double cell = std::max(cutoffSigmas * maxWidth, 1e-30);
    const glm::ivec3 dims = glm::clamp(glm::ivec3(glm::floor(box.extent() / cell)) + 1, glm::ivec3(1), glm::ivec3(512));
    const Vec3 cellSize = glm::max(box.extent() / Vec3(dims), Vec3(cell));
    auto cellOf = [&](const glm::vec3& p) {
        return glm::clamp(glm::ivec3(glm::floor((Vec3(p) - box.min) / cellSize)), glm::ivec3(0), dims - 1);
    };
    auto flat = [&](const glm::ivec3& c) { return (size_t(c.z) * dims.y + c.y) * dims.x + c.x; };
    std::vector<uint32_t> start(size_t(dims.x) * dims.y * dims.z + 1, 0), order(n);
    for (size_t i = 0; i < n; ++i) ++start[flat(cellOf(samples.positions[i])) + 1];
    for (size_t c = 1; c < start.size(); ++c) start[c] += start[c - 1];
    std::vector<uint32_t> fill(start.begin(), start.end() - 1);
    for (size_t i = 0; i < n; ++i) order[fill[flat(cellOf(samples.positions[i]))]++] = uint32_t(i);
    const glm::ivec3 reach = glm::ivec3(glm::ceil(Vec3(cell) / cellSize));

    tbb::parallel_for(tbb::blocked_range<size_t>(0, n, 256), [&](const tbb::blocked_range<size_t>& r) {
        for (size_t i = r.begin(); i < r.end(); ++i) {
            const glm::vec3 b = samples.positions[i];
            const glm::ivec3 c = cellOf(b), lo = glm::max(c - reach, glm::ivec3(0)), hi = glm::min(c + reach, dims - 1);
            const double si2 = double(samples.widths[i]) * samples.widths[i];
            double sum = 0.0;
            for (int z = lo.z; z <= hi.z; ++z)
                for (int y = lo.y; y <= hi.y; ++y)
                    for (int x = lo.x; x <= hi.x; ++x) {
                        const size_t f = flat({x, y, z});
                        for (uint32_t k = start[f]; k < start[f + 1]; ++k) {
                            const uint32_t j = order[k];
                            // int_V gamma_i gamma_j / (2 pi s_i^2)^1.5, in closed form: the
                            // product is a Gaussian of variance s_i^2 s_j^2 / (s_i^2 + s_j^2).
                            const double sj2 = double(samples.widths[j]) * samples.widths[j];
                            const glm::vec3 d = b - samples.positions[j];
                            const double r2 = glm::dot(d, d);
                            if (r2 > cutoffSigmas * cutoffSigmas * sj2) continue;
                            const double s2 = si2 + sj2;
                            const double productDepth = (sj2 * depth[i] + si2 * depth[j]) / s2;
                            const double productSigma = std::sqrt(si2 * sj2 / s2);
                            sum += std::pow(sj2 / s2, 1.5) * std::exp(-0.5 * r2 / s2) *
                                   normalCdf(productDepth / productSigma);
                        }
                    }
            // int_V gamma_i / (2 pi s_i^2)^1.5 over the sum; the sample itself keeps it positive.
            weights[i] = float(normalCdf(depth[i] / std::sqrt(si2)) / sum);
        }
    });
    return weights;
}

}  // namespace lucent
