#include "core/density_field.h"

#include <algorithm>
#include <fstream>

#include "core/error.h"
#include "core/input_file.h"
#include "core/internal/openvdb_plugin.h"

namespace lucent {

// ---- layers -------------------------------------------------------------------

LayeredDensity::LayeredDensity(int axis, std::vector<double> values, const Bounds3& objectBounds)
    : axis_(axis), values_(std::move(values)) {
    lo_ = objectBounds.min[axis];
    width_ = std::max(objectBounds.extent()[axis], 1e-300) / double(values_.size());
}

int LayeredDensity::slabOf(double c) const {
    const double s = std::floor((c - lo_) / width_);
    return int(std::clamp(s, 0.0, double(values_.size() - 1)));
}

double LayeredDensity::at(const Vec3& p) const { return values_[slabOf(p[axis_])]; }

double LayeredDensity::integrate(const Vec3& a, const Vec3& b) const {
    const double length = glm::length(b - a);
    const double ca = a[axis_], cb = b[axis_];
    if (length == 0.0) return 0.0;
    int sa = slabOf(ca), sb = slabOf(cb);
    if (sa == sb) return values_[sa] * length;
    // Walk the slabs between the two ends; the fraction of the segment in each slab
    // is the fraction of the coordinate range it covers.
    const double range = cb - ca;
    double total = 0.0, prev = 0.0;
    const int step = sb > sa ? 1 : -1;
    for (int s = sa; s != sb; s += step) {
        const double plane = lo_ + width_ * (step > 0 ? s + 1 : s);
        const double f = std::clamp((plane - ca) / range, prev, 1.0);
        total += values_[s] * (f - prev) * length;
        prev = f;
    }
    total += values_[sb] * (1.0 - prev) * length;
    return total;
}

std::optional<DensitySlab> LayeredDensity::slabAround(const Vec3& p) const {
    const int s = slabOf(p[axis_]);
    // The outermost slabs reach past the bounds: the field holds their value there.
    const double lo = s == 0 ? -kInfinity : lo_ + width_ * s;
    const double hi = s + 1 == int(values_.size()) ? kInfinity : lo_ + width_ * (s + 1);
    return DensitySlab{axis_, lo, hi};
}

double LayeredDensity::minimum() const { return *std::min_element(values_.begin(), values_.end()); }
double LayeredDensity::maximum() const { return *std::max_element(values_.begin(), values_.end()); }

// ---- grid ---------------------------------------------------------------------

GridDensity::GridDensity(int nx, int ny, int nz, const Bounds3& bounds, std::vector<float> values)
    : nx_(nx), ny_(ny), nz_(nz), bounds_(bounds), values_(std::move(values)) {
    const Vec3 cells(std::max(nx - 1, 1), std::max(ny - 1, 1), std::max(nz - 1, 1));
    cell_ = bounds.extent() / cells;
    auto [lo, hi] = std::minmax_element(values_.begin(), values_.end());
    min_ = std::min(0.0, double(*lo));  // zero outside the lattice
    max_ = *hi;
}

double GridDensity::atIndexSpace(const Vec3& u) const {
    auto split = [](double x, int n, int& i, double& f) {
        if (n == 1) {
            i = 0;
            f = 0.0;
            return;
        }
        x = std::clamp(x, 0.0, double(n - 1));
        i = std::min(int(x), n - 2);
        f = x - i;
    };
    int i, j, k;
    double fx, fy, fz;
    split(u.x, nx_, i, fx);
    split(u.y, ny_, j, fy);
    split(u.z, nz_, k, fz);
    const int i1 = std::min(i + 1, nx_ - 1), j1 = std::min(j + 1, ny_ - 1), k1 = std::min(k + 1, nz_ - 1);
    const double c00 = node(i, j, k) * (1 - fx) + node(i1, j, k) * fx;
    const double c10 = node(i, j1, k) * (1 - fx) + node(i1, j1, k) * fx;
    const double c01 = node(i, j, k1) * (1 - fx) + node(i1, j, k1) * fx;
    const double c11 = node(i, j1, k1) * (1 - fx) + node(i1, j1, k1) * fx;
    return (c00 * (1 - fy) + c10 * fy) * (1 - fz) + (c01 * (1 - fy) + c11 * fy) * fz;
}

double GridDensity::at(const Vec3& p) const {
    if (!bounds_.contains(p)) return 0.0;
    return atIndexSpace((p - bounds_.min) / cell_);
}

double GridDensity::integrate(const Vec3& a, const Vec3& b) const {
    const double length = glm::length(b - a);
    if (length == 0.0) return 0.0;
    // Clip the segment to the lattice box (slab test), in index space.
    const Vec3 ua = (a - bounds_.min) / cell_, ub = (b - bounds_.min) / cell_;
    double s0 = 0.0, s1 = 1.0;
    if (!clipToBox(Bounds3{Vec3(0.0), Vec3(nx_ - 1, ny_ - 1, nz_ - 1)}, ua, ub - ua, s0, s1)) return 0.0;
    // Collect every parameter where the segment crosses a lattice plane; between two
    // of them the trilinear field is a cubic in s, which Simpson's rule integrates exactly.
    thread_local std::vector<double> cuts;
    cuts.assign({s0, s1});
    for (int ax = 0; ax < 3; ++ax) {
        const double d = ub[ax] - ua[ax];
        if (d == 0.0) continue;
        const double ca = ua[ax] + s0 * d, cb = ua[ax] + s1 * d;
        const int first = int(std::ceil(std::min(ca, cb))), last = int(std::floor(std::max(ca, cb)));
        for (int plane = first; plane <= last; ++plane) {
            const double s = (plane - ua[ax]) / d;
            if (s > s0 && s < s1) cuts.push_back(s);
        }
    }
    std::sort(cuts.begin(), cuts.end());
    double total = 0.0;
    for (size_t c = 0; c + 1 < cuts.size(); ++c) {
        const double p = cuts[c], q = cuts[c + 1];
        if (q <= p) continue;
        auto f = [&](double s) { return atIndexSpace(ua + s * (ub - ua)); };
        total += (q - p) / 6.0 * (f(p) + 4.0 * f(0.5 * (p + q)) + f(q));
    }
    return total * length;
}

std::unique_ptr<GridDensity> loadRawGrid(const std::filesystem::path& file, int nx, int ny, int nz,
                                         const Bounds3& bounds) {
    const std::string name = file.string();
    const uint64_t expected = uint64_t(nx) * uint64_t(ny) * uint64_t(nz) * sizeof(float);
    checkMemoryBudget(expected, file, "density grid");
    const uint64_t actual = regularFileSize(file, "density grid file");
    std::ifstream in(file, std::ios::binary);
    if (!in) throw Error(name, "cannot open density grid file");
    if (actual != expected)
        throw Error(name, "grid file holds " + std::to_string(actual) + " bytes but dims [" + std::to_string(nx) +
                              ", " + std::to_string(ny) + ", " + std::to_string(nz) + "] need " +
                              std::to_string(expected));
    std::vector<float> values(size_t(nx) * ny * nz);
    in.read(reinterpret_cast<char*>(values.data()), std::streamsize(expected));
    if (!in) throw Error(name, "cannot read density grid file");
    for (size_t i = 0; i < values.size(); ++i)
        if (!std::isfinite(values[i]) || values[i] < 0.0f)
            throw Error(name, "density value " + std::to_string(i) + " is negative or not finite");
    return std::make_unique<GridDensity>(nx, ny, nz, bounds, std::move(values));
}

std::unique_ptr<GridDensity> loadVdbGrid(const std::filesystem::path& file, const std::string& gridName) {
    DenseFloatGrid grid = coreOpenVdbPlugin().readFloatGrid(file, gridName);
    return std::make_unique<GridDensity>(grid.nodes[0], grid.nodes[1], grid.nodes[2], grid.bounds,
                                         std::move(grid.values));
}

}  // namespace lucent
