#pragma once
// The one voxel layout of every grid Lucent keeps (the scattering grid the
// runtime draws, the hybrid's volumes, the discrete ordinates' moments and the
// OpenCL kernels' buffers): x fastest, then y, then z. Index arithmetic goes
// through here, never written out by hand.
#include <array>
#include <cstddef>

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

}  // namespace lucent
