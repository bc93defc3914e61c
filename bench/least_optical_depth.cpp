#include "bench/least_optical_depth.h"

#include <algorithm>
#include <cmath>
#include <queue>

namespace lucent {

LeastOpticalDepth::LeastOpticalDepth(const UnfoldedProblem& u) : box_(u.problem().domain) {
    const Vec3 e = box_.extent();
    for (int a = 0; a < 3; ++a) {
        n_[a] = std::clamp(int(std::ceil(e[a] / 2.0)) + 1, 2, 129);
        h_[a] = e[a] / (n_[a] - 1);
    }
    const size_t count = size_t(n_[0]) * n_[1] * n_[2];
    std::vector<double> sigma(count);
    depth_.assign(count, kInfinity);
    using Entry = std::pair<double, size_t>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
    for (size_t i = 0; i < count; ++i) {
        const TransportRegion* r = u.at(node(i));
        sigma[i] = r ? r->sigmaT : 0.0;
        if (r && r->source > 0.0) queue.push({depth_[i] = 0.0, i});
    }
    while (!queue.empty()) {
        const auto [d, i] = queue.top();
        queue.pop();
        if (d > depth_[i]) continue;
        const int x = int(i % n_[0]), y = int(i / n_[0] % n_[1]), z = int(i / (size_t(n_[0]) * n_[1]));
        for (int dz = -1; dz <= 1; ++dz)
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const int X = x + dx, Y = y + dy, Z = z + dz;
                    if (X < 0 || Y < 0 || Z < 0 || X >= n_[0] || Y >= n_[1] || Z >= n_[2]) continue;
                    const size_t j = index(X, Y, Z);
                    const double length = glm::length(Vec3(dx * h_[0], dy * h_[1], dz * h_[2]));
                    const double next = d + 0.5 * (sigma[i] + sigma[j]) * length;
                    if (next < depth_[j]) queue.push({depth_[j] = next, j});
                }
    }
}

double LeastOpticalDepth::operator()(const Vec3& x) const {
    double f[3];
    int c[3];
    for (int a = 0; a < 3; ++a) {
        const double t = std::clamp((x[a] - box_.min[a]) / h_[a], 0.0, double(n_[a] - 1));
        c[a] = std::min(int(t), n_[a] - 2);
        f[a] = t - c[a];
    }
    double sum = 0.0;
    for (int k = 0; k < 8; ++k) {
        double w = 1.0;
        for (int a = 0; a < 3; ++a) w *= (k >> a & 1) ? f[a] : 1.0 - f[a];
        if (w > 0.0) sum += w * depth_[index(c[0] + (k & 1), c[1] + (k >> 1 & 1), c[2] + (k >> 2 & 1))];
    }
    return sum;
}

Vec3 LeastOpticalDepth::node(size_t i) const {
    return box_.min + Vec3(double(i % n_[0]) * h_[0], double(i / n_[0] % n_[1]) * h_[1],
                           double(i / (size_t(n_[0]) * n_[1])) * h_[2]);
}

}  // namespace lucent
