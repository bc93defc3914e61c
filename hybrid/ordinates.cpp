#include "hybrid/ordinates.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.h"

namespace lucent::hybrid {

namespace {

// Positive nodes and weights of the 2n-point Gauss-Legendre rule on [-1, 1]
// (Newton's method on P_2n from the Chebyshev guesses).
void gaussLegendreHalf(int n, std::vector<double>& nodes, std::vector<double>& weights) {
    const int m = 2 * n;
    for (int i = 0; i < n; ++i) {
        double x = std::cos(kPi * (i + 0.75) / (m + 0.5)), dp = 1.0;
        for (int it = 0; it < 100; ++it) {
            double p0 = 1.0, p1 = x;
            for (int k = 2; k <= m; ++k) {
                const double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
                p0 = p1;
                p1 = p2;
            }
            dp = m * (x * p1 - p0) / (x * x - 1.0);
            const double dx = p1 / dp;
            x -= dx;
            if (std::abs(dx) < 1e-15) break;
        }
        nodes.push_back(x);
        weights.push_back(2.0 / ((1.0 - x * x) * dp * dp));
    }
}

// Level-symmetric sets LQn (Lewis and Miller, Computational Methods of Neutron
// Transport, 1984, table 4-1): direction cosines mu_i and the weight of each
// point class, normalised to 1 per octant. A class lists indices into mu; its
// points are all distinct permutations.
struct LevelSymmetric {
    std::vector<double> mu;
    std::vector<std::array<int, 3>> classes;
    std::vector<double> classWeights;
};

const LevelSymmetric& levelSymmetric(int count) {
    static const LevelSymmetric lq4{{0.3500212, 0.8688903}, {{0, 0, 1}}, {1.0 / 3.0}};
    static const LevelSymmetric lq6{{0.2666355, 0.6815076, 0.9261808}, {{0, 0, 2}, {0, 1, 1}}, {0.1761263, 0.1572071}};
    static const LevelSymmetric lq8{{0.2182179, 0.5773503, 0.7867958, 0.9511897},
                                    {{0, 0, 3}, {0, 1, 2}, {1, 1, 1}},
                                    {0.1209877, 0.0907407, 0.0925926}};
    return count == 24 ? lq4 : count == 48 ? lq6 : lq8;
}

std::vector<std::pair<Vec3, double>> octantOf(int count) {
    std::vector<std::pair<Vec3, double>> out;
    if (count <= 80) {
        const LevelSymmetric& s = levelSymmetric(count);
        for (size_t c = 0; c < s.classes.size(); ++c) {
            std::array<int, 3> idx = s.classes[c];
            std::sort(idx.begin(), idx.end());
            do {
                out.push_back({Vec3(s.mu[idx[0]], s.mu[idx[1]], s.mu[idx[2]]), s.classWeights[c]});
            } while (std::next_permutation(idx.begin(), idx.end()));
        }
        // The published cosines carry 7 digits: make each direction exactly unit
        // and the octant's weights sum to exactly 1.
        double sum = 0.0;
        for (auto& [d, w] : out) d = glm::normalize(d), sum += w;
        for (auto& [d, w] : out) w /= sum;
        return out;
    }
    const int polar = 3, azimuths = count == 120 ? 5 : 7;
    std::vector<double> mu, wmu;
    gaussLegendreHalf(polar, mu, wmu);  // weights of the positive half sum to 1
    for (int p = 0; p < polar; ++p)
        for (int a = 0; a < azimuths; ++a) {
            const double phi = (a + 0.5) * 0.5 * kPi / azimuths, s = std::sqrt(1.0 - mu[p] * mu[p]);
            out.push_back({Vec3(s * std::cos(phi), s * std::sin(phi), mu[p]), wmu[p] / azimuths});
        }
    return out;
}

}  // namespace

const std::vector<int>& ordinateCounts() {
    static const std::vector<int> counts{24, 48, 80, 120, 168};
    return counts;
}

Ordinates ordinatesFor(int count) {
    const auto& counts = ordinateCounts();
    if (std::find(counts.begin(), counts.end(), count) == counts.end()) {
        std::string list;
        for (int c : counts) list += (list.empty() ? "" : ", ") + std::to_string(c);
        throw Error("discrete ordinates: " + std::to_string(count) + " directions is not offered (choose " + list +
                    ")");
    }
    const auto octant = octantOf(count);
    Ordinates o;
    o.perOctant = int(octant.size());
    for (int oct = 0; oct < 8; ++oct) {
        const Vec3 sign((oct & 1) ? -1 : 1, (oct & 2) ? -1 : 1, (oct & 4) ? -1 : 1);
        for (const auto& [d, w] : octant) {
            o.directions.push_back(d * sign);
            o.weights.push_back(w * 0.5 * kPi);  // 1 per octant -> 4 pi in all
        }
    }
    return o;
}

VoxelCrossing voxelCrossing(const Vec3& dir, const Vec3& h) {
    // Sample each Out face on a regular grid and follow the characteristic back
    // to the face it entered by.
    constexpr int kSide = 256;
    VoxelCrossing c;
    const double volume = h.x * h.y * h.z;
    for (int out = 0; out < 3; ++out) {
        if (dir[out] <= 0.0) continue;
        const int u = (out + 1) % 3, v = (out + 2) % 3;
        std::array<double, 3> hits{}, sum{};
        for (int i = 0; i < kSide; ++i)
            for (int j = 0; j < kSide; ++j) {
                Vec3 p;
                p[out] = h[out];
                p[u] = (i + 0.5) / kSide * h[u];
                p[v] = (j + 0.5) / kSide * h[v];
                int in = out;
                double t = p[out] / dir[out];
                for (int a = 0; a < 3; ++a)
                    if (dir[a] > 0.0 && p[a] / dir[a] < t) in = a, t = p[a] / dir[a];
                hits[in] += 1.0;
                sum[in] += t;
            }
        const double area = h[u] * h[v];
        for (int in = 0; in < 3; ++in) {
            if (hits[in] == 0.0) continue;
            c.share[in][out] = hits[in] / (kSide * kSide);
            c.length[in][out] = sum[in] / hits[in];
            c.tube[in][out] = area * dir[out] * c.share[in][out] / volume;
        }
    }
    // The sampled shares carry a sampling error, largest for a face the
    // direction grazes: fitted in turn (Sinkhorn) so that each Out face is
    // wholly reached and each In face's light wholly leaves, both exactly,
    // since the solver's energy balance rests on them.
    const double inflow[3] = {dir.x / h.x, dir.y / h.y, dir.z / h.z};
    const double outArea[3] = {h.y * h.z, h.x * h.z, h.x * h.y};
    for (int round = 0; round < 200; ++round) {
        for (int in = 0; in < 3; ++in) {
            double sum = 0.0;
            for (int out = 0; out < 3; ++out) sum += c.tube[in][out];
            if (sum <= 0.0) continue;
            for (int out = 0; out < 3; ++out) c.tube[in][out] *= inflow[in] / sum;
        }
        for (int out = 0; out < 3; ++out) {
            double sum = 0.0;
            for (int in = 0; in < 3; ++in) sum += c.tube[in][out];
            const double target = outArea[out] * dir[out] / volume;
            if (sum <= 0.0) continue;
            for (int in = 0; in < 3; ++in) c.tube[in][out] *= target / sum;
        }
    }
    for (int in = 0; in < 3; ++in)
        for (int out = 0; out < 3; ++out)
            c.share[in][out] = dir[out] > 0.0 ? c.tube[in][out] * volume / (outArea[out] * dir[out]) : 0.0;
    double filled = 0.0;
    for (int in = 0; in < 3; ++in)
        for (int out = 0; out < 3; ++out) filled += c.tube[in][out] * c.length[in][out];
    for (auto& row : c.length)
        for (double& l : row) l /= filled;
    return c;
}

DeltaM deltaM(double g, int bands) {
    DeltaM d;
    d.f = g > 0.0 ? std::pow(g, bands) : 0.0;
    for (int l = 0; l < bands && l < int(d.moments.size()); ++l) d.moments[l] = (std::pow(g, l) - d.f) / (1.0 - d.f);
    return d;
}

}  // namespace lucent::hybrid
