#pragma once
// Spatially varying density: the extinction at x is sigma_t * density(x)
// (DESIGN.md). Each field integrates itself exactly along a segment, so optical
// depth has no marching error: piecewise constant fields split at their slab
// planes, trilinear grids split at voxel faces where the integrand is a cubic.
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/math.h"
#include "core/similarity.h"

namespace lucent {

// Where a piecewise-constant field holds one value: between two planes normal to an axis.
struct DensitySlab {
    int axis;
    double lo, hi;
};

class DensityField {
public:
    virtual ~DensityField() = default;
    virtual double at(const Vec3& p) const = 0;
    // Integral of density over the straight segment from a to b (per unit length).
    virtual double integrate(const Vec3& a, const Vec3& b) const = 0;
    // Smallest and largest value anywhere: bounds on light penetration depth.
    virtual double minimum() const = 0;
    virtual double maximum() const = 0;
    // The slab of constant density holding p, for fields that jump between slabs
    // (the runtime clips each Gaussian to its slab); none for continuous fields.
    virtual std::optional<DensitySlab> slabAround(const Vec3& p) const { return std::nullopt; }
};

class ConstantDensity final : public DensityField {
public:
    double at(const Vec3&) const override { return 1.0; }
    double integrate(const Vec3& a, const Vec3& b) const override { return glm::length(b - a); }
    double minimum() const override { return 1.0; }
    double maximum() const override { return 1.0; }
};

// The object's bounding box cut along one axis into equal slabs, slab k holding values[k].
class LayeredDensity final : public DensityField {
public:
    LayeredDensity(int axis, std::vector<double> values, const Bounds3& objectBounds);
    double at(const Vec3& p) const override;
    double integrate(const Vec3& a, const Vec3& b) const override;
    double minimum() const override;
    double maximum() const override;
    std::optional<DensitySlab> slabAround(const Vec3& p) const override;

private:
    int slabOf(double coordinate) const;
    int axis_;
    std::vector<double> values_;
    double lo_, width_;
};

// Values at the nodes of a regular nx*ny*nz lattice spanning bounds (x fastest),
// interpolated trilinearly; zero outside the bounds.
class GridDensity final : public DensityField {
public:
    GridDensity(int nx, int ny, int nz, const Bounds3& bounds, std::vector<float> values);
    double at(const Vec3& p) const override;
    double integrate(const Vec3& a, const Vec3& b) const override;
    double minimum() const override { return min_; }
    double maximum() const override { return max_; }

private:
    double node(int i, int j, int k) const { return values_[(size_t(k) * ny_ + j) * nx_ + i]; }
    double atIndexSpace(const Vec3& u) const;
    int nx_, ny_, nz_;
    Bounds3 bounds_;
    Vec3 cell_;
    std::vector<float> values_;
    double min_ = 0.0, max_ = 0.0;
};

// Raw little-endian float32 file; the size must match dims exactly.
std::unique_ptr<GridDensity> loadRawGrid(const std::filesystem::path& file, int nx, int ny, int nz,
                                         const Bounds3& bounds);
// A float grid of an OpenVDB file, densified over its active bounding box.
std::unique_ptr<GridDensity> loadVdbGrid(const std::filesystem::path& file, const std::string& gridName);

// A field given in an object's own space, queried in the world: the object
// stands where placement puts it. A world segment is placement.scale times as
// long as its object-space preimage, so its integral is that much larger.
// Slabs are the object's and need not be normal to a world axis: none is reported
// (only preprocessing, which runs in object space, asks for them).
class PlacedDensity final : public DensityField {
public:
    PlacedDensity(std::unique_ptr<DensityField> field, const Similarity& placement)
        : field_(std::move(field)), placement_(placement) {}
    double at(const Vec3& p) const override { return field_->at(placement_.inversePoint(p)); }
    double integrate(const Vec3& a, const Vec3& b) const override {
        return placement_.scale * field_->integrate(placement_.inversePoint(a), placement_.inversePoint(b));
    }
    double minimum() const override { return field_->minimum(); }
    double maximum() const override { return field_->maximum(); }

private:
    std::unique_ptr<DensityField> field_;
    Similarity placement_;
};

}  // namespace lucent
