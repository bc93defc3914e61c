#include "hybrid/internal/dom_solver.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.h"
#include "core/refraction.h"
#include "core/spherical_harmonics.h"
#include "hybrid/internal/sweep_halo.h"

namespace lucent::hybrid {

namespace {

constexpr int kPartials = 1024;

template <typename T>
cl::Buffer constBuffer(const cl::Context& cx, const std::vector<T>& values) {
    return cl::Buffer(cx, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, std::max<size_t>(values.size(), 1) * sizeof(T),
                      const_cast<T*>(values.data()));
}

cl_int4 int4Of(const std::array<int, 3>& d) { return {{d[0], d[1], d[2], 0}}; }

}  // namespace

size_t DomSolver::faceOffset(int face, const std::array<int, 3>& d, int directions) {
    const size_t cells[3] = {size_t(d[1]) * d[2], size_t(d[0]) * d[2], size_t(d[0]) * d[1]};
    size_t off = 0;  // face 6: the end of the last face, the size of them all
    for (int f = 0; f < face; ++f) off += cells[f / 2];
    return off * directions;
}

std::vector<cl_int> DomSolver::innerFaces(const DomGrid& grid, int* count) {
    const GridIndex index = grid.index();
    const auto& d = grid.dims;
    std::vector<cl_int> faces(3 * index.count(), -1);
    auto wanted = [&](size_t v) { return grid.extinction[v].a != 0.0f; };
    auto air = [&](size_t v) { return glm::vec3(grid.extinction[v]) == glm::vec3(0.0f); };
    *count = 0;
    for (int k = 0; k < d[2]; ++k)
        for (int j = 0; j < d[1]; ++j)
            for (int i = 0; i < d[0]; ++i) {
                const size_t v = index(i, j, k);
                const int c[3] = {i, j, k};
                for (int a = 0; a < 3; ++a) {
                    if (c[a] + 1 >= d[a]) continue;
                    const size_t u = index(i + (a == 0), j + (a == 1), k + (a == 2));
                    if ((wanted(v) && air(u)) || (air(v) && wanted(u))) faces[3 * v + a] = (*count)++;
                }
            }
    return faces;
}

size_t DomSolver::largestBufferFor(size_t voxels, int bands) { return voxels * bands * bands * sizeof(glm::vec4); }

size_t DomSolver::bytesFor(const std::array<int, 3>& d, int directions, int bands, bool shared) {
    const size_t voxels = size_t(d[0]) * d[1] * d[2];
    // source, flux, last flux, total; three float4 materials; two face buffers; two boundaries (three shared)
    return 4 * largestBufferFor(voxels, bands) + voxels * 3 * sizeof(glm::vec4) +
           (size_t(d[0]) * (d[1] + d[2])) * directions / 8 * sizeof(glm::vec4) +
           (shared ? 3 : 2) * faceOffset(6, d, directions) * sizeof(glm::vec4);
}

DomSolver::DomSolver(const ClDevice& device, const DomGrid& grid, int directions, int bands,
                     const BoundaryFlags& reflective, SweepHalo* halo)
    : grid_(grid), ordinates_(ordinatesFor(directions)), moments_(bands * bands), halo_(halo) {
    if (bands < 1 || bands > kMaxBands)
        throw Error("discrete ordinates: 1 to " + std::to_string(kMaxBands) + " bands of moments, not " +
                    std::to_string(bands));
    const int k = ordinates_.perOctant, n = 8 * k;
    // More moments than directions would be aliased: the directions cannot tell them apart.
    if (moments_ > n)
        throw Error("discrete ordinates: " + std::to_string(moments_) +
                    " moments need at least as many directions, not " + std::to_string(n));
    program_ = device.buildSource("#define DOM_K " + std::to_string(k) + "\n#define DOM_BANDS " +
                                      std::to_string(bands) + "\n#define DOM_M " + std::to_string(moments_) +
                                      "\n#line 1\n" + hybridKernel("dom_sweep.cl"),
                                  "dom_sweep.cl");
    sweep_ = cl::Kernel(program_, "dom_sweep");
    scatter_ = cl::Kernel(program_, "dom_scatter");
    power_ = cl::Kernel(program_, "dom_power");
    for (int f = 0; f < 6; ++f) reflectiveMask_ |= reflective[f] ? 1 << f : 0;

    // The directions' moments, weights and voxel crossings (edges may differ per axis).
    std::vector<float> ylm(size_t(n) * moments_), weights(n), crossing(size_t(k) * 27);
    std::vector<double> y(moments_);
    for (int i = 0; i < n; ++i) {
        evaluateSh(bands, ordinates_.directions[i], y);
        for (int m = 0; m < moments_; ++m) ylm[size_t(i) * moments_ + m] = float(y[m]);
        weights[i] = float(ordinates_.weights[i]);
    }
    for (int d = 0; d < k; ++d) {
        const VoxelCrossing c = voxelCrossing(ordinates_.directions[d], grid.edges);
        for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b) {
                crossing[d * 27 + a * 3 + b] = float(c.share[a][b]);
                crossing[d * 27 + 9 + a * 3 + b] = float(c.tube[a][b]);
                crossing[d * 27 + 18 + a * 3 + b] = float(c.length[a][b]);
            }
    }
    const cl::Context& cx = device.context;
    const size_t voxels = grid.count(), values = voxels * moments_;
    extinction_ = constBuffer(cx, grid.extinction);
    scattering_ = constBuffer(cx, grid.scattering);
    phase_ = constBuffer(cx, grid.phase);
    ylm_ = constBuffer(cx, ylm);
    weights_ = constBuffer(cx, weights);
    crossing_ = constBuffer(cx, crossing);
    source_ = zeroBuffer(cx, values * sizeof(glm::vec4));
    flux_ = zeroBuffer(cx, values * sizeof(glm::vec4));
    lastFlux_ = zeroBuffer(cx, values * sizeof(glm::vec4));
    total_ = zeroBuffer(cx, values * sizeof(glm::vec4));
    const auto& dm = grid.dims;
    yFace_ = zeroBuffer(cx, size_t(dm[0]) * dm[2] * k * sizeof(glm::vec4));
    zFace_ = zeroBuffer(cx, size_t(dm[0]) * dm[1] * k * sizeof(glm::vec4));
    for (cl::Buffer& b : boundary_) b = zeroBuffer(cx, faceOffset(6, dm, n) * sizeof(glm::vec4));
    haloIn_ = zeroBuffer(cx, (halo ? faceOffset(6, dm, n) : 1) * sizeof(glm::vec4));
    partial_ = zeroBuffer(cx, kPartials * sizeof(glm::vec4));
    // The inner boundary: per face, Fresnel's reflectance of each direction
    // leaving the medium by it, at its angle to the boundary's normal there (a
    // direction the staircase lets out but the boundary would not: kept inside).
    int faces = 0;
    std::vector<cl_int> innerFace = grid.ior != 1.0 ? innerFaces(grid, &faces) : std::vector<cl_int>{-1};
    mirrors_ = faces > 0;
    const size_t mirrorBytes = size_t(faces) * n * sizeof(glm::vec4);
    if (mirrors_)
        device.checkMemory(2 * mirrorBytes + mirrorBytes / 4, mirrorBytes,
                           "the inner boundary's reflections (" + std::to_string(faces) + " voxel faces)");
    std::vector<float> fresnel(std::max<size_t>(1, size_t(faces) * n));
    if (mirrors_) {
        if (grid.boundaryNormal.size() != grid.count()) throw Error("internal: discrete ordinates without normals");
        const GridIndex index = grid.index();
        for (size_t v = 0; v < grid.count(); ++v)
            for (int a = 0; a < 3; ++a) {
                const int f = innerFace[3 * v + a];
                if (f < 0) continue;
                const std::array<int, 3> c = index.cell(v);
                const size_t u = index(c[0] + (a == 0), c[1] + (a == 1), c[2] + (a == 2));
                const Vec3 sum = Vec3(grid.boundaryNormal[v] + grid.boundaryNormal[u]);
                const Vec3 normal = glm::length(sum) > 0.0 ? glm::normalize(sum) : Vec3(0.0);
                for (int i = 0; i < n; ++i) {
                    const double cosine = glm::dot(ordinates_.directions[i], normal);
                    fresnel[size_t(f) * n + i] = cosine > 0.0 ? float(fresnelReflectance(cosine, grid.ior)) : 1.0f;
                }
            }
    }
    innerFace_ = constBuffer(cx, innerFace);
    fresnel_ = constBuffer(cx, fresnel);
    for (cl::Buffer& b : mirror_) b = zeroBuffer(cx, std::max<size_t>(1, size_t(faces) * n) * sizeof(glm::vec4));

    sweep_.setArg(0, extinction_);
    sweep_.setArg(1, source_);
    sweep_.setArg(3, yFace_);
    sweep_.setArg(4, zFace_);
    sweep_.setArg(7, ylm_);
    sweep_.setArg(8, weights_);
    sweep_.setArg(9, crossing_);
    sweep_.setArg(10, int4Of(dm));
    sweep_.setArg(11, float(std::max({grid.edges.x, grid.edges.y, grid.edges.z})));
    sweep_.setArg(13, cl_int(reflectiveMask_));
    sweep_.setArg(16, innerFace_);
    sweep_.setArg(19, fresnel_);
    sweep_.setArg(20, cl_int(mirrors_));
    sweep_.setArg(21, haloIn_);
    sweep_.setArg(22, cl_int(halo ? halo->mask() : 0));
    scatter_.setArg(2, source_);
    scatter_.setArg(3, scattering_);
    scatter_.setArg(4, phase_);
}

void DomSolver::setSource(cl::CommandQueue& queue, const std::vector<glm::vec4>& source) {
    if (source.size() != grid_.count() * moments_) throw Error("internal: discrete ordinates source of wrong size");
    queue.enqueueWriteBuffer(source_, CL_TRUE, 0, source.size() * sizeof(glm::vec4), source.data());
}

void DomSolver::scatterGeneration(cl::CommandQueue& queue) {
    scatter_.setArg(0, flux_);
    scatter_.setArg(1, total_);
    queue.enqueueNDRangeKernel(scatter_, cl::NullRange, cl::NDRange(grid_.count()));
    std::swap(flux_, lastFlux_);
    queue.enqueueFillBuffer(flux_, 0.0f, 0, grid_.count() * moments_ * sizeof(glm::vec4));
}

void DomSolver::setUncollidedFlux(cl::CommandQueue& queue, const std::vector<glm::vec4>& flux) {
    if (flux.size() != grid_.count() * moments_) throw Error("internal: discrete ordinates flux of wrong size");
    queue.enqueueWriteBuffer(flux_, CL_TRUE, 0, flux.size() * sizeof(glm::vec4), flux.data());
    scatterGeneration(queue);
    Rgb power(0.0);  // generation zero's, as iterate() measures each generation
    for (size_t v = 0; v < grid_.count(); ++v)
        for (int c = 0; c < 3; ++c) power[c] += flux[v * moments_][c];
    if (halo_) halo_->sum(&power[0], 3);
    total_power_ += power;
    previous_power_ = power;
    queue.finish();
}

Rgb DomSolver::iterate(cl::CommandQueue& queue) {
    const auto& d = grid_.dims;
    sweep_.setArg(2, flux_);
    sweep_.setArg(5, boundary_[swaps_ % 2]);
    sweep_.setArg(6, boundary_[(swaps_ + 1) % 2]);
    sweep_.setArg(17, mirror_[swaps_ % 2]);
    sweep_.setArg(18, mirror_[(swaps_ + 1) % 2]);
    for (int octant = 0; octant < 8; ++octant) {
        sweep_.setArg(12, cl_int(octant));
        // Shared with other ranks, the sweep goes in blocks of z (KBA): each
        // block's diagonals j + k once the upstream ranks' faces are in.
        const int blocks = halo_ ? halo_->blocks() : 1;
        for (int b = 0; b < blocks; ++b) {
            const std::array<int, 2> k = halo_ ? halo_->block(b) : std::array<int, 2>{0, d[2]};
            if (halo_) halo_->receive(queue, haloIn_, octant, b);
            for (int diagonal = k[0]; diagonal <= d[1] - 1 + k[1] - 1; ++diagonal) {
                const int kFirst = std::max(k[0], diagonal - (d[1] - 1)), kLast = std::min(k[1] - 1, diagonal);
                sweep_.setArg(14, cl_int(diagonal));
                sweep_.setArg(15, cl_int(kFirst));
                queue.enqueueNDRangeKernel(sweep_, cl::NullRange, cl::NDRange(size_t(kLast - kFirst + 1)),
                                           cl::NDRange(1));
            }
            if (halo_) halo_->send(queue, boundary_[(swaps_ + 1) % 2], octant, b);
        }
    }
    ++swaps_;
    power_.setArg(0, flux_);
    power_.setArg(1, partial_);
    power_.setArg(2, cl_int(grid_.count()));
    queue.enqueueNDRangeKernel(power_, cl::NullRange, cl::NDRange(kPartials));
    std::vector<glm::vec4> partial = read(queue, partial_, kPartials);
    scatterGeneration(queue);
    Rgb sum(0.0);
    for (int i = 0; i < kPartials; ++i)
        for (int c = 0; c < 3; ++c) sum[c] += partial[i][c];
    if (halo_) halo_->sum(&sum[0], 3);
    return sum;
}

void DomSolver::addTail(cl::CommandQueue& queue, const Rgb& factor) {
    cl::Kernel add(program_, "dom_add_scaled");
    add.setArg(0, total_);
    add.setArg(1, lastFlux_);
    add.setArg(2, cl_float4{{float(factor.r), float(factor.g), float(factor.b), 0.0f}});
    queue.enqueueNDRangeKernel(add, cl::NullRange, cl::NDRange(grid_.count()));
}

bool DomSolver::step(cl::CommandQueue& queue, double tolerance) {
    if (run_.converged) return false;
    const Rgb power = iterate(queue);
    total_power_ += power;
    const int i = run_.iterations++;
    bool done = i >= 2;  // the first generations (uncollided, once scattered) do not yet decay geometrically
    Rgb tail(0.0);
    const Rgb lastRatio = run_.ratio;
    for (int c = 0; c < 3; ++c) {
        if (!(power[c] > 0.0) || !(total_power_[c] > 0.0)) {  // nothing left in this channel
            run_.ratio[c] = 0.0;
            continue;
        }
        run_.ratio[c] = previous_power_[c] > 0.0 ? power[c] / previous_power_[c] : 1.0;
        if (run_.ratio[c] >= 1.0) {
            done = false;
            continue;
        }
        tail[c] = run_.ratio[c] / (1.0 - run_.ratio[c]);
        // Done when what is still to come is small, or when the ratio has
        // settled (the generations decay as the slowest mode): a ratio known
        // to tolerance (1 - r) gives the tail r / (1 - r) to about tolerance.
        const bool small = power[c] * tail[c] <= tolerance * total_power_[c];
        const bool settled = i >= 3 && std::abs(run_.ratio[c] - lastRatio[c]) <= tolerance * (1.0 - run_.ratio[c]);
        done = done && (small || settled);
    }
    previous_power_ = power;
    if (done) {
        addTail(queue, tail);
        run_.converged = true;
    }
    return !done;
}

DomSolver::Run DomSolver::run(cl::CommandQueue& queue, double tolerance, int maxIterations,
                              const std::function<void(int)>& afterEach) {
    while (run_.iterations < maxIterations) {
        const bool more = step(queue, tolerance);
        if (afterEach) afterEach(run_.iterations - 1);
        if (!more) break;
    }
    return run_;
}

std::vector<glm::vec4> DomSolver::totalFlux(cl::CommandQueue& queue) {
    return read(queue, total_, grid_.count() * moments_);
}

std::vector<glm::vec4> DomSolver::boundaryRadiance(cl::CommandQueue& queue) {
    return read(queue, boundary_[swaps_ % 2], faceOffset(6, grid_.dims, 8 * ordinates_.perOctant));
}

std::vector<glm::vec4> DomSolver::read(cl::CommandQueue& queue, cl::Buffer& buffer, size_t count) {
    std::vector<glm::vec4> out(count);
    queue.enqueueReadBuffer(buffer, CL_TRUE, 0, count * sizeof(glm::vec4), out.data());
    return out;
}

}  // namespace lucent::hybrid
