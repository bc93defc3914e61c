#include "hybrid/voxelisation.h"

#include <algorithm>
#include <cmath>

#include <tbb/parallel_for.h>

#include "core/error.h"

namespace lucent::hybrid {

GridShape gridShapeFor(const Bounds3& objectBounds, int resolution) {
    if (resolution < 2 * kBlock || resolution > 1024)
        throw Error("grid resolution " + std::to_string(resolution) + " is outside [8, 1024]");
    const Vec3 extent = objectBounds.extent();
    const double longest = std::max({extent.x, extent.y, extent.z});
    GridShape s;
    s.voxel = longest / double(resolution - 2);
    for (int a = 0; a < 3; ++a) {
        const int inner = std::max(1, int(std::ceil(extent[a] / s.voxel - 1e-9)));
        s.dims[a] = (inner + 2 + kBlock - 1) / kBlock * kBlock;
    }
    s.origin = objectBounds.center() - 0.5 * s.voxel * Vec3(s.dims[0], s.dims[1], s.dims[2]);
    return s;
}

void gaussianBlur(std::vector<float>& values, const std::array<int, 3>& dims, double sigmaVoxels) {
    const int radius = std::max(1, int(std::ceil(2.5 * sigmaVoxels)));
    std::vector<double> weights(2 * radius + 1);
    double total = 0.0;
    for (int k = -radius; k <= radius; ++k)
        total += weights[k + radius] = std::exp(-0.5 * k * k / (sigmaVoxels * sigmaVoxels));
    for (double& w : weights) w /= total;
    const size_t stride[3] = {1, size_t(dims[0]), size_t(dims[0]) * dims[1]};
    std::vector<float> out(values.size());
    for (int axis = 0; axis < 3; ++axis) {
        tbb::parallel_for(0, dims[2], [&](int z) {
            for (int y = 0; y < dims[1]; ++y)
                for (int x = 0; x < dims[0]; ++x) {
                    const int c[3] = {x, y, z};
                    const size_t at = x + stride[1] * y + stride[2] * z;
                    double sum = 0.0;
                    for (int k = -radius; k <= radius; ++k) {
                        const int j = std::clamp(c[axis] + k, 0, dims[axis] - 1);
                        sum += weights[k + radius] * values[at + (j - c[axis]) * ptrdiff_t(stride[axis])];
                    }
                    out[at] = float(sum);
                }
        });
        values.swap(out);
    }
}

std::vector<float> Voxelisation::viewRefraction() const {
    std::vector<float> out;
    if (!refracting) return out;
    out.reserve(4 * refraction.size());
    for (const glm::vec4& r : refraction) out.insert(out.end(), {r.x, r.y, r.z, r.w});
    return out;
}

Voxelisation voxelise(const VolumeObject& object, int resolution) {
    Voxelisation v;
    v.shape = gridShapeFor(object.mesh().bounds(), resolution);
    const GridShape& s = v.shape;
    const auto& d = s.dims;
    v.material.assign(s.count(), glm::vec4(0.0f));
    std::vector<float> blocked(s.count(), 0.0f);
    const double half = 0.5 * s.voxel;
    // One ray along +z per sub-sample column finds where the column is inside;
    // the two sub-samples of each voxel along z only look them up. A task owns a
    // row of voxels (two rows of sub-samples), so no two tasks write one voxel.
    tbb::parallel_for(0, d[1], [&](int y) {
        std::vector<Interval> inside;
        for (int sy = 2 * y; sy < 2 * y + 2; ++sy)
            for (int sx = 0; sx < 2 * d[0]; ++sx) {
                const Vec3 base = s.origin + Vec3((sx + 0.5) * half, (sy + 0.5) * half, 0.0);
                inside.clear();
                object.boundary().insideIntervals(base, Vec3(0, 0, 1), d[2] * s.voxel, inside, false);
                size_t next = 0;
                for (int sz = 0; sz < 2 * d[2]; ++sz) {
                    const double t = (sz + 0.5) * half;
                    while (next < inside.size() && inside[next].t1 < t) ++next;
                    if (next == inside.size() || inside[next].t0 > t) continue;
                    const Vec3 p = base + Vec3(0, 0, t);
                    const size_t at = size_t(sx / 2) + d[0] * (size_t(y) + size_t(d[1]) * (sz / 2));
                    if (object.insideBlocker(p)) {
                        blocked[at] += 1.0f / 8.0f;
                        continue;
                    }
                    v.material[at] += glm::vec4(glm::vec3(object.extinction(p) / 8.0), 1.0f / 8.0f);
                }
            }
    });
    for (size_t i = 0; i < s.count(); ++i)
        if (blocked[i] >= 0.5f) v.material[i] = glm::vec4(0.0f, 0.0f, 0.0f, kOpaque);

    // The index follows the occupancy (air is 1), blurred over 0.75 voxel so that
    // its gradient, by central differences, is smooth enough to march (thesis 4.3).
    const double ior = object.desc().medium.ior;
    v.refracting = ior != 1.0;
    v.ior = ior;
    v.refraction.assign(s.count(), glm::vec4(1.0f, 0.0f, 0.0f, 0.0f));
    if (!v.refracting) return v;
    std::vector<float> n(s.count());
    for (size_t i = 0; i < s.count(); ++i) n[i] = float(1.0 + (ior - 1.0) * std::max(v.material[i].a, 0.0f));
    gaussianBlur(n, d, 0.75);
    const size_t stride[3] = {1, size_t(d[0]), size_t(d[0]) * d[1]};
    tbb::parallel_for(0, d[2], [&](int z) {
        for (int y = 0; y < d[1]; ++y)
            for (int x = 0; x < d[0]; ++x) {
                const int c[3] = {x, y, z};
                const size_t at = x + stride[1] * y + stride[2] * z;
                glm::vec4& r = v.refraction[at];
                r.x = n[at];
                for (int a = 0; a < 3; ++a) {
                    const int lo = std::max(c[a] - 1, 0), hi = std::min(c[a] + 1, d[a] - 1);
                    if (hi == lo) continue;
                    const float dn = n[at + (hi - c[a]) * stride[a]] - n[at - (c[a] - lo) * stride[a]];
                    r[a + 1] = float(dn / ((hi - lo) * s.voxel));
                }
            }
    });
    return v;
}

}  // namespace lucent::hybrid
