#include "hybrid/internal/photon_marcher.h"

#include <cmath>

namespace lucent::hybrid {

PhotonMarcher::PhotonMarcher(const ClDevice& device, const cl::Program& program, const Voxelisation& grid,
                             const Rgb& albedo, const RayMap& rays, double step)
    : march_(program, "march"),
      transfer_(program, "transfer"),
      rayCount_(rays.rays.size()),
      voxels_(grid.shape.count()),
      emitted_(rays.emitted) {
    const cl::Context& cx = device.context;
    // A channel's whole emitted power is 2^kFixedBits units, so sums cannot overflow 64 bits.
    for (int c = 0; c < 3; ++c)
        unitsPerWatt_[c] = emitted_[c] > 0.0 ? std::ldexp(1.0, clshared::kFixedBits) / emitted_[c] : 0.0;
    rays_ = cl::Buffer(cx, CL_MEM_READ_WRITE | CL_MEM_COPY_HOST_PTR,
                       std::max<size_t>(1, rayCount_) * sizeof(clshared::PhotonRay),
                       rayCount_ ? const_cast<clshared::PhotonRay*>(rays.rays.data()) : nullptr);
    if (!rayCount_) rays_ = cl::Buffer(cx, CL_MEM_READ_WRITE, sizeof(clshared::PhotonRay));
    material_ = cl::Buffer(cx, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, voxels_ * sizeof(glm::vec4),
                           const_cast<glm::vec4*>(grid.material.data()));
    refraction_ = cl::Buffer(cx, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, voxels_ * sizeof(glm::vec4),
                             const_cast<glm::vec4*>(grid.refraction.data()));
    std::vector<cl_ulong> zeros(3 * voxels_, 0);
    for (cl::Buffer& d : deposit_)
        d = cl::Buffer(cx, CL_MEM_READ_WRITE | CL_MEM_COPY_HOST_PTR, zeros.size() * sizeof(cl_ulong), zeros.data());
    cl_ulong none[7] = {0, 0, 0, 0, 0, 0, 0};
    tallies_ = cl::Buffer(cx, CL_MEM_READ_WRITE | CL_MEM_COPY_HOST_PTR, sizeof(none), none);

    const auto& d = grid.shape.dims;
    march_.setArg(0, rays_);
    march_.setArg(1, material_);
    march_.setArg(2, refraction_);
    march_.setArg(4, tallies_);
    march_.setArg(5, cl_int4{{d[0], d[1], d[2], 0}});
    march_.setArg(
        6, cl_float4{{float(grid.shape.origin.x), float(grid.shape.origin.y), float(grid.shape.origin.z), 0.0f}});
    march_.setArg(7, float(grid.shape.voxel));
    march_.setArg(8, float(step));
    march_.setArg(10, float4Of(albedo));
    march_.setArg(11, float4Of(unitsPerWatt_));
    march_.setArg(12, cl_int(grid.refracting));
    march_.setArg(13, float(grid.ior));
    Rgb wattsPerUnit(0.0);
    for (int c = 0; c < 3; ++c) wattsPerUnit[c] = unitsPerWatt_[c] > 0.0 ? 1.0 / unitsPerWatt_[c] : 0.0;
    transfer_.setArg(2, float4Of(wattsPerUnit));
}

void PhotonMarcher::enqueueMarch(cl::CommandQueue& queue, int steps, int which, std::vector<cl::Event>* after,
                                 cl::Event* done) {
    if (!rayCount_) return;
    march_.setArg(3, deposit_[which]);
    march_.setArg(9, cl_int(steps));
    const cl_ulong zero = 0;
    queue.enqueueFillBuffer(tallies_, zero, 6 * sizeof(cl_ulong), sizeof(cl_ulong), after);
    after = nullptr;
    queue.enqueueNDRangeKernel(march_, cl::NullRange, cl::NDRange(rayCount_), cl::NullRange, after, done);
}

void PhotonMarcher::enqueueTransfer(cl::CommandQueue& queue, int which, cl::Buffer& source,
                                    std::vector<cl::Event>* after, cl::Event* done) {
    transfer_.setArg(0, deposit_[which]);
    transfer_.setArg(1, source);
    queue.enqueueNDRangeKernel(transfer_, cl::NullRange, cl::NDRange(voxels_), cl::NullRange, after, done);
}

MarchTallies PhotonMarcher::tallies(cl::CommandQueue& queue) {
    cl_ulong t[6];
    queue.enqueueReadBuffer(tallies_, CL_TRUE, 0, sizeof(t), t);
    MarchTallies out;
    for (int c = 0; c < 3; ++c) {
        const double w = unitsPerWatt_[c] > 0.0 ? 1.0 / unitsPerWatt_[c] : 0.0;
        out.absorbed[c] = double(t[c]) * w;
        out.escaped[c] = double(t[3 + c]) * w;
    }
    return out;
}

size_t PhotonMarcher::marching(cl::CommandQueue& queue) {
    cl_ulong n = 0;
    queue.enqueueReadBuffer(tallies_, CL_TRUE, 6 * sizeof(cl_ulong), sizeof(n), &n);
    return size_t(n);
}

std::vector<clshared::PhotonRay> PhotonMarcher::rays(cl::CommandQueue& queue) {
    std::vector<clshared::PhotonRay> out(rayCount_);
    if (rayCount_) queue.enqueueReadBuffer(rays_, CL_TRUE, 0, rayCount_ * sizeof(clshared::PhotonRay), out.data());
    return out;
}

Rgb PhotonMarcher::deposited(cl::CommandQueue& queue, int which) {
    std::vector<cl_ulong> d(3 * voxels_);
    queue.enqueueReadBuffer(deposit_[which], CL_TRUE, 0, d.size() * sizeof(cl_ulong), d.data());
    Rgb sum(0.0);
    for (size_t i = 0; i < voxels_; ++i)
        for (int c = 0; c < 3; ++c) sum[c] += double(d[3 * i + c]);
    for (int c = 0; c < 3; ++c) sum[c] = unitsPerWatt_[c] > 0.0 ? sum[c] / unitsPerWatt_[c] : 0.0;
    return sum;
}

}  // namespace lucent::hybrid
