#include "hybrid/internal/lattice.h"

#include <algorithm>

#include "core/refraction.h"

namespace lucent::hybrid {

namespace {
constexpr size_t kInterfaceFloat4PerBlock = 6 * 16;
}  // namespace

double latticeBoundaryReflectance(double ior) {
    if (ior == 1.0) return 0.0;
    const double ri = diffuseFresnelReflectance(ior);
    const double a = (1.0 + ri) / (1.0 - ri);
    const double aLattice = std::max(1.0, 2.0 * a / 3.0);
    return (aLattice - 1.0) / (aLattice + 1.0);
}

size_t Lattice::bytesFor(size_t voxels, bool blocked) {
    // f, (out), source, two materials, fluence, absorbed, escaped, two interfaces
    const size_t perVoxel = sizeof(glm::vec4) * (6 + (blocked ? 0 : 6) + 6) +
                            (blocked ? 2 * kInterfaceFloat4PerBlock * sizeof(glm::vec4) / 64 : 0);
    return voxels * perVoxel;
}

Lattice::Lattice(const ClDevice& device, const cl::Program& program, const Voxelisation& grid, const Rgb& albedo,
                 bool blocked, int subSteps, double g)
    : grid_(grid),
      albedo_(albedo),
      latticeExtinctionScale_(Rgb(1.0) - albedo * g),
      blocked_(blocked),
      subSteps_(std::max(1, subSteps)),
      voxels_(grid.shape.count()),
      collide_(program, "lattice_collide"),
      stream_(program, "lattice_stream"),
      blocks_(program, "lattice_blocks"),
      probes_(program, "gather_probes"),
      finish_(program, "finish") {
    const cl::Context& cx = device.context;
    const size_t v4 = sizeof(glm::vec4);
    f_ = zeroBuffer(cx, 6 * voxels_ * v4);
    source_ = zeroBuffer(cx, voxels_ * v4);
    fluence_ = zeroBuffer(cx, voxels_ * v4);
    absorbed_ = zeroBuffer(cx, voxels_ * v4);
    escaped_ = zeroBuffer(cx, voxels_ * v4);
    trueMaterial_ = cl::Buffer(cx, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, voxels_ * v4,
                               const_cast<glm::vec4*>(grid.material.data()));
    std::vector<glm::vec4> reduced = grid.material;
    for (glm::vec4& m : reduced) m *= glm::vec4(glm::vec3(latticeExtinctionScale_), 1.0f);
    material_ = cl::Buffer(cx, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, voxels_ * v4, reduced.data());
    // sigma'_s / sigma'_t = a (1 - g) / (1 - a g)
    const Rgb latticeAlbedo = albedo * (1.0 - g) / glm::max(latticeExtinctionScale_, Rgb(1e-12));
    const auto& d = grid.shape.dims;
    const cl_int4 dims{{d[0], d[1], d[2], 0}};
    const float lambda = float(grid.shape.voxel);
    // The share of diffuse light the boundary keeps inside (lattice.cl).
    const float r = float(latticeBoundaryReflectance(grid.ior));
    if (!blocked_) {
        out_ = zeroBuffer(cx, 6 * voxels_ * v4);
        collide_.setArg(0, f_);
        collide_.setArg(1, source_);
        collide_.setArg(2, material_);
        collide_.setArg(3, out_);
        collide_.setArg(4, fluence_);
        collide_.setArg(5, absorbed_);
        collide_.setArg(6, float4Of(latticeAlbedo));
        collide_.setArg(7, lambda);
        stream_.setArg(0, out_);
        stream_.setArg(1, material_);
        stream_.setArg(2, f_);
        stream_.setArg(3, escaped_);
        stream_.setArg(4, absorbed_);
        stream_.setArg(5, dims);
        stream_.setArg(6, r);
        return;
    }
    // Blocks that hold any medium (or blocker) are launched; the rest are air.
    const int bx = d[0] / kBlock, by = d[1] / kBlock, bz = d[2] / kBlock;
    std::vector<cl_int> active, isActive(size_t(bx) * by * bz, 0);
    for (int k = 0; k < bz; ++k)
        for (int j = 0; j < by; ++j)
            for (int i = 0; i < bx; ++i) {
                bool any = false;
                for (int z = 0; z < kBlock && !any; ++z)
                    for (int y = 0; y < kBlock && !any; ++y)
                        for (int x = 0; x < kBlock && !any; ++x) {
                            const size_t at =
                                (i * kBlock + x) + d[0] * ((j * kBlock + y) + size_t(d[1]) * (k * kBlock + z));
                            any = grid.material[at].a != 0.0f;
                        }
                const int b = i + bx * (j + by * k);
                if (any) active.push_back(b), isActive[b] = 1;
            }
    activeCount_ = int(active.size());
    active_ =
        cl::Buffer(cx, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, std::max<size_t>(1, active.size()) * sizeof(cl_int),
                   active.empty() ? isActive.data() : active.data());
    blockActive_ =
        cl::Buffer(cx, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, isActive.size() * sizeof(cl_int), isActive.data());
    for (cl::Buffer& b : interface_) b = zeroBuffer(cx, isActive.size() * kInterfaceFloat4PerBlock * v4);
    blocks_.setArg(0, f_);
    blocks_.setArg(1, source_);
    blocks_.setArg(2, material_);
    blocks_.setArg(3, fluence_);
    blocks_.setArg(4, absorbed_);
    blocks_.setArg(5, escaped_);
    blocks_.setArg(8, active_);
    blocks_.setArg(9, blockActive_);
    blocks_.setArg(10, dims);
    blocks_.setArg(11, float4Of(latticeAlbedo));
    blocks_.setArg(12, lambda);
    blocks_.setArg(13, cl_int(subSteps_));
    blocks_.setArg(14, r);
}

void Lattice::enqueueLaunch(cl::CommandQueue& queue, std::vector<cl::Event>* after, cl::Event* done) {
    if (!blocked_) {
        queue.enqueueNDRangeKernel(collide_, cl::NullRange, cl::NDRange(voxels_), cl::NullRange, after);
        const auto& d = grid_.shape.dims;
        queue.enqueueNDRangeKernel(stream_, cl::NullRange, cl::NDRange(d[0], d[1], d[2]), cl::NullRange, nullptr, done);
        return;
    }
    if (activeCount_ == 0) return;
    // Interfaces alternate: this launch reads what the previous one wrote.
    blocks_.setArg(6, interface_[launches_ % 2]);
    blocks_.setArg(7, interface_[(launches_ + 1) % 2]);
    ++launches_;
    queue.enqueueNDRangeKernel(blocks_, cl::NullRange, cl::NDRange(size_t(activeCount_) * 64), cl::NDRange(64), after,
                               done);
}

void Lattice::chooseProbes(int count) {
    std::vector<cl_int> inside;
    for (size_t i = 0; i < voxels_; ++i)
        if (grid_.material[i].a > 0.0f) inside.push_back(cl_int(i));
    std::vector<cl_int> probes;
    const size_t n = std::min<size_t>(count, inside.size());
    for (size_t k = 0; k < n; ++k) probes.push_back(inside[(k * inside.size()) / n + (inside.size() / n) / 2]);
    probeCount_ = int(probes.size());
    if (probes.empty()) return;
    const cl::Context cx = collide_.getInfo<CL_KERNEL_CONTEXT>();
    probeIndex_ =
        cl::Buffer(cx, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, probes.size() * sizeof(cl_int), probes.data());
    probeOut_ = cl::Buffer(cx, CL_MEM_READ_WRITE, probes.size() * sizeof(glm::vec4));
    probes_.setArg(0, fluence_);
    probes_.setArg(1, probeIndex_);
    probes_.setArg(2, probeOut_);
}

Rgb Lattice::probeSum(cl::CommandQueue& queue) {
    if (probeCount_ == 0) return Rgb(0.0);
    queue.enqueueNDRangeKernel(probes_, cl::NullRange, cl::NDRange(probeCount_));
    Rgb sum(0.0);
    for (const glm::vec4& v : read(queue, probeOut_, probeCount_)) sum += Rgb(v.r, v.g, v.b);
    return sum;
}

std::vector<glm::vec4> Lattice::read(cl::CommandQueue& queue, cl::Buffer& buffer, size_t count) {
    std::vector<glm::vec4> out(count);
    queue.enqueueReadBuffer(buffer, CL_TRUE, 0, count * sizeof(glm::vec4), out.data());
    return out;
}

std::vector<glm::vec4> Lattice::fluenceTally(cl::CommandQueue& queue) { return read(queue, fluence_, voxels_); }

LatticeTotals Lattice::totals(cl::CommandQueue& queue) {
    LatticeTotals t;
    auto add = [](Rgb& to, const std::vector<glm::vec4>& v) {
        for (const glm::vec4& x : v) to += Rgb(x.r, x.g, x.b);
    };
    add(t.absorbed, read(queue, absorbed_, voxels_));
    add(t.escaped, read(queue, escaped_, voxels_));
    add(t.inFlight, read(queue, f_, 6 * voxels_));
    add(t.inFlight, read(queue, source_, voxels_));
    if (blocked_)
        add(t.inFlight,
            read(queue, interface_[launches_ % 2], interface_[0].getInfo<CL_MEM_SIZE>() / sizeof(glm::vec4)));
    return t;
}

ScatteringGrid Lattice::finish(cl::CommandQueue& queue) {
    const cl::Context cx = collide_.getInfo<CL_KERNEL_CONTEXT>();
    cl::Buffer radiance(cx, CL_MEM_WRITE_ONLY, voxels_ * sizeof(glm::vec4));
    const double voxel = grid_.shape.voxel;
    finish_.setArg(0, fluence_);
    finish_.setArg(1, trueMaterial_);
    finish_.setArg(2, material_);
    finish_.setArg(3, radiance);
    finish_.setArg(4, float4Of(albedo_));
    finish_.setArg(5, float(voxel));
    finish_.setArg(6, float(kInvFourPi / (voxel * voxel * voxel)));
    queue.enqueueNDRangeKernel(finish_, cl::NullRange, cl::NDRange(voxels_));
    const std::vector<glm::vec4> r = read(queue, radiance, voxels_);
    ScatteringGrid g;
    g.bounds = grid_.shape.bounds();
    g.dims = grid_.shape.dims;
    g.source.resize(3 * voxels_);
    g.extinction.resize(3 * voxels_);
    for (size_t i = 0; i < voxels_; ++i)
        for (int c = 0; c < 3; ++c) {
            g.source[3 * i + c] = r[i][c];
            g.extinction[3 * i + c] = grid_.material[i].a > 0.0f ? grid_.material[i][c] : 0.0f;
        }
    g.ior = grid_.ior;
    g.refraction = grid_.viewRefraction();
    return g;
}

}  // namespace lucent::hybrid
