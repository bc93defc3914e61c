#include "preprocess/sample_weights.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "core/math.h"

namespace lucent {

namespace {

double normalCdf(double x) { return 0.5 * std::erfc(-x / std::sqrt(2.0)); }

}  // namespace

double insideShare(const WeightedSample& s, const glm::vec3& p, double sigma) {
    if (!std::isfinite(s.thickness)) return 1.0;
    // u: the depth under the nearest boundary, along the line to the image.
    const glm::vec3 axis = s.position - s.image;
    const double length = glm::length(axis);
    if (!(length > 0.0)) return 1.0;
    const double u = glm::dot(p - 0.5f * (s.position + s.image), axis) / length;
    return std::max(0.0, normalCdf((double(s.thickness) - u) / sigma) - normalCdf(-u / sigma));
}

double heldInside(const WeightedSample& s) {
    if (!std::isfinite(s.thickness)) return 1.0;
    return insideShare(s, s.position, s.width) + insideShare(s, s.image, s.width);
}

std::vector<float> partitionOfUnityWeights(const std::vector<WeightedSample>& samples, double reachSigmas) {
    const size_t n = samples.size();
    std::vector<float> weights(n, 1.0f);
    if (n == 0) return weights;
    float maxWidth = 0.0f;
    Bounds3 box;
    for (const auto& s : samples) {
        maxWidth = std::max(maxWidth, s.width);
        box.extend(Vec3(s.position));
    }
    // Bin centres into cells as wide as the largest reach.
    const double cell = std::max(reachSigmas * maxWidth, 1e-30);
    const glm::ivec3 dims = glm::clamp(glm::ivec3(glm::floor(box.extent() / cell)) + 1, glm::ivec3(1), glm::ivec3(512));
    const Vec3 cellSize = glm::max(box.extent() / Vec3(dims), Vec3(cell));
    auto cellOf = [&](const glm::vec3& p) {
        return glm::clamp(glm::ivec3(glm::floor((Vec3(p) - box.min) / cellSize)), glm::ivec3(0), dims - 1);
    };
    auto flat = [&](const glm::ivec3& c) { return (size_t(c.z) * dims.y + c.y) * dims.x + c.x; };
    std::vector<uint32_t> start(size_t(dims.x) * dims.y * dims.z + 1, 0), order(n);
    for (const auto& s : samples) ++start[flat(cellOf(s.position)) + 1];
    for (size_t c = 1; c < start.size(); ++c) start[c] += start[c - 1];
    std::vector<uint32_t> fill(start.begin(), start.end() - 1);
    for (size_t i = 0; i < n; ++i) order[fill[flat(cellOf(samples[i].position))]++] = uint32_t(i);
    const glm::ivec3 reach = glm::ivec3(glm::ceil(Vec3(cell) / cellSize));

    // sum_j v_j c_ij with c_ij = int_in k_i k_j / int_in k_i, in closed form: the
    // product of two Gaussians is a Gaussian of variance s_i^2 s_j^2 / (s_i^2 + s_j^2)
    // centred between them. Where the region is thick around i, mirror symmetry
    // turns it into int gamma_i (gamma_j + gamma_j*) / int gamma_i over all space.
    auto overlap = [&](size_t i, const std::vector<double>& v) {
        const WeightedSample& a = samples[i];
        const glm::ivec3 c = cellOf(a.position), lo = glm::max(c - reach, glm::ivec3(0)),
                         hi = glm::min(c + reach, dims - 1);
        const double si2 = double(a.width) * a.width;
        const bool thin = std::isfinite(a.thickness);
        const double own = std::max(heldInside(a), 1e-3);  // int_in k_i / int gamma_i
        double sum = 0.0;
        for (int z = lo.z; z <= hi.z; ++z)
            for (int y = lo.y; y <= hi.y; ++y)
                for (int x = lo.x; x <= hi.x; ++x) {
                    const size_t f = flat({x, y, z});
                    for (uint32_t k = start[f]; k < start[f + 1]; ++k) {
                        const WeightedSample& b = samples[order[k]];
                        if (b.region != a.region) continue;
                        const double sj2 = double(b.width) * b.width;
                        const double s2 = si2 + sj2;
                        const double reach2 = reachSigmas * reachSigmas * std::max(si2, sj2);
                        const double ratio = sj2 / s2;  // ratio^1.5, without pow's cost in this hot loop
                        const double scale = ratio * std::sqrt(ratio) * v[order[k]];
                        if (!thin) {
                            for (const glm::vec3& centre : {b.position, b.image}) {
                                const glm::vec3 d = a.position - centre;
                                const double r2 = glm::dot(d, d);
                                if (r2 <= reach2) sum += scale * std::exp(-0.5 * r2 / s2);
                            }
                            continue;
                        }
                        const double product = std::sqrt(si2 * sj2 / s2);
                        for (const glm::vec3& mine : {a.position, a.image})
                            for (const glm::vec3& centre : {b.position, b.image}) {
                                const glm::vec3 d = mine - centre;
                                const double r2 = glm::dot(d, d);
                                if (r2 > reach2) continue;
                                const glm::vec3 middle = glm::vec3((sj2 * Vec3(mine) + si2 * Vec3(centre)) / s2);
                                sum += scale * std::exp(-0.5 * r2 / s2) * insideShare(a, middle, product) / own;
                            }
                    }
                }
        return sum;  // the sample itself keeps it positive
    };
    // The Galerkin system sum_j c_ij w_j = 1, with w locally constant: w_i = 1 / sum_j c_ij.
    // (Solving the system exactly, by multiplicative sweeps, measured no better.)
    const std::vector<double> ones(n, 1.0);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, n, 256), [&](const tbb::blocked_range<size_t>& r) {
        for (size_t i = r.begin(); i < r.end(); ++i) weights[i] = float(1.0 / std::max(overlap(i, ones), 1e-30));
    });
    return weights;
}

std::vector<float> volumeShareWeights(const std::vector<float>& widths, double sampledVolume) {
    double total = 0.0;
    for (float s : widths) total += std::pow(2.0 * kPi * double(s) * s, 1.5);
    return std::vector<float>(widths.size(), total > 0.0 ? float(sampledVolume / total) : 0.0f);
}

}  // namespace lucent
