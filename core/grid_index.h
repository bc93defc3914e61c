#pragma once
// The one voxel layout of every grid Lucent keeps (the scattering grid the
// runtime draws, the hybrid's volumes, the discrete ordinates' moments and the
// OpenCL kernels' buffers): x fastest, then y, then z. Index arithmetic goes
// through here, never written out by hand.
#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

namespace lucent {

struct GridIndex {
    std::array<int, 3> dims{0, 0, 0};

    size_t count() const { return size_t(dims[0]) * size_t(dims[1]) * size_t(dims[2]); }
    size_t operator()(int i, int j, int k) const {
        return size_t(i) + size_t(dims[0]) * (size_t(j) + size_t(dims[1]) * size_t(k));
    }
    size_t operator()(const std::array<int, 3>& c) const { return (*this)(c[0], c[1], c[2]); }
    std::array<int, 3> cell(size_t v) const {
        const size_t row = size_t(dims[0]), slice = row * size_t(dims[1]);
        return {int(v % row), int(v / row % size_t(dims[1])), int(v / slice)};
    }
};

// The values of the box [lo, hi) of a grid of `dims` cells, `perCell` values
// per cell, in the box's own order (x fastest).
template <typename T>
std::vector<T> boxOf(const std::vector<T>& grid, const std::array<int, 3>& dims, const std::array<int, 3>& lo,
                     const std::array<int, 3>& hi, size_t perCell = 1) {
    const GridIndex whole{dims}, box{{hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]}};
    std::vector<T> out;
    out.reserve(box.count() * perCell);
    for (int k = lo[2]; k < hi[2]; ++k)
        for (int j = lo[1]; j < hi[1]; ++j) {
            const auto row = grid.begin() + ptrdiff_t(whole(lo[0], j, k) * perCell);
            out.insert(out.end(), row, row + ptrdiff_t(size_t(hi[0] - lo[0]) * perCell));
        }
    return out;
}

// The inverse: a box's values put back into the grid.
template <typename T>
void putBox(std::vector<T>& grid, const std::array<int, 3>& dims, const std::array<int, 3>& lo,
            const std::array<int, 3>& hi, const std::vector<T>& box, size_t perCell = 1) {
    const GridIndex whole{dims};
    auto from = box.begin();
    const ptrdiff_t row = ptrdiff_t(size_t(hi[0] - lo[0]) * perCell);
    for (int k = lo[2]; k < hi[2]; ++k)
        for (int j = lo[1]; j < hi[1]; ++j, from += row)
            std::copy(from, from + row, grid.begin() + ptrdiff_t(whole(lo[0], j, k) * perCell));
}

}  // namespace lucent
