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
    if (values.empty()) return cl::Buffer(cx, CL_MEM_READ_ONLY, sizeof(T));
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

DomSolver::InnerBoundary DomSolver::innerBoundary(const DomGrid& grid) {
    const GridIndex index = grid.index();
    const auto& d = grid.dims;
    InnerBoundary out;
    if (grid.ior == 1.0) return out;
    if (grid.boundaryNormal.size() != grid.count()) throw Error("internal: discrete ordinates without normals");
    out.faces.assign(6 * index.count(), -1);
    auto wanted = [&](size_t v) { return grid.extinction[v].a != 0.0f; };
    auto air = [&](size_t v) { return glm::vec3(grid.extinction[v]) == glm::vec3(0.0f); };
    for (int k = 0; k < d[2]; ++k)
        for (int j = 0; j < d[1]; ++j)
            for (int i = 0; i < d[0]; ++i) {
                const size_t v = index(i, j, k);
                const int c[3] = {i, j, k};
                for (int a = 0; a < 3; ++a) {
                    if (c[a] + 1 >= d[a]) continue;
                    const size_t u = index(i + (a == 0), j + (a == 1), k + (a == 2));
                    if (!(wanted(v) && air(u)) && !(air(v) && wanted(u))) continue;
                    const int f = int(out.normals.size());
                    out.faces[6 * v + 2 * a + 1] = f;  // v's face to +axis is u's to -axis
                    out.faces[6 * u + 2 * a] = f;
                    const glm::vec3 sum = grid.boundaryNormal[v] + grid.boundaryNormal[u];
                    out.normals.push_back(glm::length(sum) > 0.0f ? glm::normalize(sum) : glm::vec3(0.0f));
                }
            }
    return out;
}

std::vector<size_t> DomSolver::volumeBytes(int bands, bool mirrors) {
    const size_t moments = size_t(bands) * bands * sizeof(glm::vec4);
    return {sizeof(glm::vec4), sizeof(glm::vec4), sizeof(glm::vec4), mirrors ? 6 * sizeof(cl_int) : 0,
            moments,           moments,           moments,           moments};
}

namespace {
int shareOf(const std::array<int, 3>& dims, const DomPool& pool) {
    const int blocks = BlockTiling(dims, pool.edge).blocks();
    return std::clamp(int(std::ceil(pool.share * blocks - 1e-9)), 1, blocks);
}
}  // namespace

bool DomSolver::pooled(const std::array<int, 3>& dims, const DomPool& pool) {
    return pool.share > 0.0 && shareOf(dims, pool) < BlockTiling(dims, pool.edge).blocks();
}

int DomSolver::slotsFor(const std::array<int, 3>& dims, const DomPool& pool) {
    return pooled(dims, pool) ? shareOf(dims, pool) : 1;
}

size_t DomSolver::largestBufferFor(const std::array<int, 3>& dims, int bands, const DomPool& pool) {
    const std::array<int, 3> d = pooled(dims, pool) ? BlockTiling(dims, pool.edge).maxDims() : dims;
    return size_t(d[0]) * d[1] * d[2] * bands * bands * sizeof(glm::vec4);
}

size_t DomSolver::hostBytesFor(const std::array<int, 3>& dims, int bands, const DomPool& pool, bool refracts) {
    if (!pooled(dims, pool)) return 0;
    size_t perVoxel = 0;
    for (size_t b : volumeBytes(bands, refracts)) perVoxel += b;
    return GridIndex{dims}.count() * perVoxel;
}

size_t DomSolver::bytesFor(const std::array<int, 3>& dims, int directions, int bands, bool shared,
                           const DomPool& pool) {
    const std::array<int, 3> d = pooled(dims, pool) ? BlockTiling(dims, pool.edge).maxDims() : dims;
    const int slots = slotsFor(dims, pool);
    // Per slot: source, flux, last flux, total and three float4 materials; two
    // face buffers; two boundaries (three shared or pooled).
    const size_t voxels = size_t(d[0]) * d[1] * d[2];
    return slots * (4 * largestBufferFor(d, bands) + voxels * 3 * sizeof(glm::vec4)) +
           (size_t(d[0]) * (d[1] + d[2])) * directions / 8 * sizeof(glm::vec4) +
           (shared || pooled(dims, pool) ? 3 : 2) * faceOffset(6, d, directions) * sizeof(glm::vec4);
}

DomSolver::DomSolver(const ClDevice& device, const DomGrid& grid, int directions, int bands,
                     const BoundaryFlags& reflective, SweepHalo* halo, const DomPool& pool)
    : grid_(grid),
      ordinates_(ordinatesFor(directions)),
      moments_(bands * bands),
      tiling_(grid.dims, pooled(grid.dims, pool) ? pool.edge : std::max({grid.dims[0], grid.dims[1], grid.dims[2], 1})),
      halo_(halo) {
    if (bands < 1 || bands > kMaxBands)
        throw Error("discrete ordinates: 1 to " + std::to_string(kMaxBands) + " bands of moments, not " +
                    std::to_string(bands));
    const int k = ordinates_.perOctant, n = 8 * k;
    // More moments than directions would be aliased: the directions cannot tell them apart.
    if (moments_ > n)
        throw Error("discrete ordinates: " + std::to_string(moments_) +
                    " moments need at least as many directions, not " + std::to_string(n));
    for (int f = 0; f < 6; ++f) reflectiveMask_ |= reflective[f] ? 1 << f : 0;
    if (tiling_.blocks() > 1 && (reflectiveMask_ != 0 || halo))
        throw Error("internal: a device pool with reflective faces or MPI ranks");
    program_ = device.buildSource("#define DOM_K " + std::to_string(k) + "\n#define DOM_BANDS " +
                                      std::to_string(bands) + "\n#define DOM_M " + std::to_string(moments_) +
                                      "\n#line 1\n" + hybridKernel("dom_sweep.cl"),
                                  "dom_sweep.cl");
    sweep_ = cl::Kernel(program_, "dom_sweep");
    scatter_ = cl::Kernel(program_, "dom_scatter");
    power_ = cl::Kernel(program_, "dom_power");
    add_ = cl::Kernel(program_, "dom_add_scaled");
    gatherZero_ = cl::Kernel(program_, "dom_gather_zero");
    takeShape_ = cl::Kernel(program_, "dom_take_shape");

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
    ylm_ = constBuffer(cx, ylm);
    weights_ = constBuffer(cx, weights);
    crossing_ = constBuffer(cx, crossing);
    const std::array<int, 3> dm = tiling_.maxDims();
    yFace_ = zeroBuffer(cx, size_t(dm[0]) * dm[2] * k * sizeof(glm::vec4));
    zFace_ = zeroBuffer(cx, size_t(dm[0]) * dm[1] * k * sizeof(glm::vec4));
    for (cl::Buffer& b : boundary_) b = zeroBuffer(cx, faceOffset(6, dm, n) * sizeof(glm::vec4));
    haloIn_ = zeroBuffer(cx, (halo || tiling_.blocks() > 1 ? faceOffset(6, dm, n) : 1) * sizeof(glm::vec4));
    partial_ = zeroBuffer(cx, kPartials * sizeof(glm::vec4));
    leaving_.resize(size_t(tiling_.blocks()) * 3);
    for (int o = 0; o < 8; ++o) order_[o] = tiling_.wavefronts(o);

    // The inner boundary: per face, Fresnel's reflectance of each direction
    // leaving the medium by it, at its angle to the boundary's normal there (a
    // direction the staircase lets out but the boundary would not: kept inside).
    const InnerBoundary inner =
        grid.innerFace.empty() ? innerBoundary(grid) : InnerBoundary{grid.innerFace, grid.faceNormal};
    const size_t faces = inner.normals.size();
    mirrors_ = faces > 0;
    const size_t mirrorBytes = faces * n * sizeof(glm::vec4);
    if (mirrors_)
        device.checkMemory(2 * mirrorBytes + mirrorBytes / 4, mirrorBytes,
                           "the inner boundary's reflections (" + std::to_string(faces) + " voxel faces)");
    std::vector<float> fresnel(std::max<size_t>(1, faces * n));
    for (size_t f = 0; f < faces; ++f)
        for (int i = 0; i < n; ++i) {
            const double cosine = glm::dot(ordinates_.directions[i], Vec3(inner.normals[f]));
            fresnel[f * n + i] = cosine > 0.0 ? float(fresnelReflectance(cosine, grid.ior)) : 1.0f;
        }
    fresnel_ = constBuffer(cx, fresnel);
    for (cl::Buffer& b : mirror_) b = zeroBuffer(cx, std::max<size_t>(1, faces * n) * sizeof(glm::vec4));

    // The volumes: with a pool holding every block, all are resident from the
    // start (zeros) and what is set goes straight to the device.
    pool_ =
        std::make_unique<BlockPool>(cx, tiling_, volumeBytes(bands, mirrors_), slotsFor(grid.dims, pool), pool.spillTo);
    const cl::CommandQueue& queue = device.marchQueue;
    if (pool_->holdsAll())
        for (int b = 0; b < tiling_.blocks(); ++b) pool_->acquire(queue, b, 0, ~0u);
    setVolume(queue, kExtinction, grid.extinction, 1);
    setVolume(queue, kScattering, grid.scattering, 1);
    setVolume(queue, kPhase, grid.phase, 1);
    if (mirrors_) setVolume(queue, kInnerFace, inner.faces, 6);

    sweep_.setArg(3, yFace_);
    sweep_.setArg(4, zFace_);
    sweep_.setArg(7, ylm_);
    sweep_.setArg(8, weights_);
    sweep_.setArg(9, crossing_);
    sweep_.setArg(11, float(std::max({grid.edges.x, grid.edges.y, grid.edges.z})));
    sweep_.setArg(13, cl_int(reflectiveMask_));
    sweep_.setArg(19, fresnel_);
    sweep_.setArg(20, cl_int(mirrors_));
    sweep_.setArg(21, haloIn_);
}

DomSolver::~DomSolver() = default;

const BlockPool::Traffic& DomSolver::traffic() const { return pool_->traffic(); }

template <typename T>
void DomSolver::setVolume(const cl::CommandQueue& queue, Volume volume, const std::vector<T>& values, size_t perCell) {
    if (tiling_.blocks() == 1) {
        pool_->set(queue, 0, volume, values.data());
        return;
    }
    for (int b = 0; b < tiling_.blocks(); ++b)
        pool_->set(queue, b, volume, boxOf(values, grid_.dims, tiling_.lo(b), tiling_.hi(b), perCell).data());
}

void DomSolver::setSource(cl::CommandQueue& queue, const std::vector<glm::vec4>& source) {
    if (source.size() != grid_.count() * moments_) throw Error("internal: discrete ordinates source of wrong size");
    setVolume(queue, kSource, source, size_t(moments_));
}

Rgb DomSolver::scatterGeneration(cl::CommandQueue& queue) {
    std::vector<glm::vec4> partial(size_t(kPartials) * tiling_.blocks());
    const unsigned need = 1u << kFlux | 1u << kTotal | 1u << kScattering | 1u << kPhase;
    for (int b = 0; b < tiling_.blocks(); ++b) {
        pool_->newWavefront();
        const int slot = pool_->acquire(queue, b, need, 1u << kSource | 1u << kLastFlux);
        const size_t voxels = tiling_.voxels(b);
        cl::Buffer& flux = pool_->buffer(slot, kFlux);
        power_.setArg(0, flux);
        power_.setArg(1, partial_);
        power_.setArg(2, cl_int(voxels));
        queue.enqueueNDRangeKernel(power_, cl::NullRange, cl::NDRange(kPartials));
        queue.enqueueReadBuffer(partial_, CL_FALSE, 0, kPartials * sizeof(glm::vec4), &partial[size_t(b) * kPartials]);
        scatter_.setArg(0, flux);
        scatter_.setArg(1, pool_->buffer(slot, kTotal));
        scatter_.setArg(2, pool_->buffer(slot, kSource));
        scatter_.setArg(3, pool_->buffer(slot, kScattering));
        scatter_.setArg(4, pool_->buffer(slot, kPhase));
        queue.enqueueNDRangeKernel(scatter_, cl::NullRange, cl::NDRange(voxels));
        queue.enqueueFillBuffer(pool_->buffer(slot, kLastFlux), 0.0f, 0, voxels * moments_ * sizeof(glm::vec4));
        pool_->written(slot, 1u << kTotal | 1u << kSource | 1u << kLastFlux);
    }
    // The flux just scattered is the last flux; the cleared one takes the next generation.
    pool_->swapVolumes(kFlux, kLastFlux);
    queue.finish();
    Rgb sum(0.0);
    for (const glm::vec4& p : partial)
        for (int c = 0; c < 3; ++c) sum[c] += p[c];
    return sum;
}

void DomSolver::setUncollidedFlux(cl::CommandQueue& queue, const std::vector<glm::vec4>& flux,
                                  const std::vector<glm::vec4>& sources) {
    if (flux.size() != grid_.count() * moments_) throw Error("internal: discrete ordinates flux of wrong size");
    setVolume(queue, kFlux, flux, size_t(moments_));
    if (!sources.empty()) {
        if (sources.size() != flux.size() || tiling_.blocks() > 1)
            throw Error("internal: a first-collided source of wrong size, or pooled");
        std::vector<cl_int> at;
        std::vector<glm::vec4> shape;
        SourcesShape s;
        for (size_t v = 0; v < grid_.count(); ++v) {
            const glm::vec4 q = sources[v * moments_];
            if (q.r <= 0.0f && q.g <= 0.0f && q.b <= 0.0f) continue;
            at.push_back(cl_int(v));
            shape.push_back(q);
            for (int c = 0; c < 3; ++c) s.total[c] += q[c];
        }
        s.voxels = at.size();
        const cl::Context cx = queue.getInfo<CL_QUEUE_CONTEXT>();
        s.at = constBuffer(cx, at);
        s.shape = constBuffer(cx, shape);
        s.gathered = zeroBuffer(cx, std::max<size_t>(1, at.size()) * sizeof(glm::vec4));
        s.flux = constBuffer(cx, flux);
        sourcesShape_ = std::move(s);
    }
    // Generation zero's light, as iterate() measures each generation; summed
    // over the ranks in the first step, since a failure here must reach the
    // ranks before they talk (transport.h).
    uncollidedPower_ = scatterGeneration(queue);
    queue.finish();
}

void DomSolver::receiveFaces(cl::CommandQueue& queue, int octant, int b) {
    const std::array<int, 3> d = tiling_.dims(b), c = tiling_.coords(b);
    const int k = ordinates_.perOctant, n = 8 * k;
    for (int a = 0; a < 3; ++a) {
        const bool down = (octant >> a) & 1;  // the sweep runs towards -axis: it enters by the + face
        std::array<int, 3> up = c;
        up[a] += down ? 1 : -1;
        const int from = tiling_.at(up);
        if (from < 0) continue;
        const std::vector<glm::vec4>& faces = leaving_[size_t(from) * 3 + a];
        const size_t cells = faces.size() / k;
        const size_t first = faceOffset(2 * a + down, d, n) / n;  // the face's first cell
        queue.enqueueWriteBufferRect(haloIn_, CL_FALSE, {octant * k * sizeof(glm::vec4), first, 0}, {0, 0, 0},
                                     {k * sizeof(glm::vec4), cells, 1}, n * sizeof(glm::vec4), 0, k * sizeof(glm::vec4),
                                     0, faces.data());
    }
}

void DomSolver::keepFaces(cl::CommandQueue& queue, int octant, int b) {
    const std::array<int, 3> d = tiling_.dims(b), c = tiling_.coords(b);
    const int k = ordinates_.perOctant, n = 8 * k;
    const size_t cellsOf[3] = {size_t(d[1]) * d[2], size_t(d[0]) * d[2], size_t(d[0]) * d[1]};
    for (int a = 0; a < 3; ++a) {
        const bool down = (octant >> a) & 1;  // it leaves by the - face
        std::array<int, 3> next = c;
        next[a] += down ? -1 : 1;
        if (tiling_.at(next) < 0) continue;
        std::vector<glm::vec4>& faces = leaving_[size_t(b) * 3 + a];
        faces.resize(cellsOf[a] * k);
        const size_t first = faceOffset(2 * a + !down, d, n) / n;
        queue.enqueueReadBufferRect(boundary_[(swaps_ + 1) % 2], CL_FALSE, {octant * k * sizeof(glm::vec4), first, 0},
                                    {0, 0, 0}, {k * sizeof(glm::vec4), cellsOf[a], 1}, n * sizeof(glm::vec4), 0,
                                    k * sizeof(glm::vec4), 0, faces.data());
    }
}

void DomSolver::sweepBlock(cl::CommandQueue& queue, int octant, int b) {
    const unsigned need = 1u << kExtinction | 1u << kSource | 1u << kFlux | (mirrors_ ? 1u << kInnerFace : 0u);
    const int slot = pool_->acquire(queue, b, need);
    sweep_.setArg(0, pool_->buffer(slot, kExtinction));
    sweep_.setArg(1, pool_->buffer(slot, kSource));
    sweep_.setArg(2, pool_->buffer(slot, kFlux));
    sweep_.setArg(16, pool_->buffer(slot, kInnerFace));
    const std::array<int, 3> d = tiling_.dims(b), c = tiling_.coords(b);
    sweep_.setArg(10, int4Of(d));
    // The faces that take in what a neighbouring block or rank upstream left.
    int mask = halo_ ? halo_->mask() : 0;
    for (int a = 0; a < 3; ++a) {
        mask |= c[a] > 0 ? 1 << 2 * a : 0;
        mask |= c[a] + 1 < tiling_.counts()[a] ? 1 << (2 * a + 1) : 0;
    }
    sweep_.setArg(22, cl_int(mask));
    if (tiling_.blocks() > 1) receiveFaces(queue, octant, b);
    // Shared with other ranks, the sweep goes in blocks of z (KBA): each
    // block's diagonals j + k once the upstream ranks' faces are in.
    const int stages = halo_ ? halo_->blocks() : 1;
    for (int z = 0; z < stages; ++z) {
        const std::array<int, 2> kz = halo_ ? halo_->block(z) : std::array<int, 2>{0, d[2]};
        if (halo_) halo_->receive(queue, haloIn_, octant, z);
        for (int diagonal = kz[0]; diagonal <= d[1] - 1 + kz[1] - 1; ++diagonal) {
            const int kFirst = std::max(kz[0], diagonal - (d[1] - 1)), kLast = std::min(kz[1] - 1, diagonal);
            sweep_.setArg(14, cl_int(diagonal));
            sweep_.setArg(15, cl_int(kFirst));
            queue.enqueueNDRangeKernel(sweep_, cl::NullRange, cl::NDRange(size_t(kLast - kFirst + 1)), cl::NDRange(1));
        }
        if (halo_) halo_->send(queue, boundary_[(swaps_ + 1) % 2], octant, z);
    }
    pool_->written(slot, 1u << kFlux);
    if (tiling_.blocks() > 1) keepFaces(queue, octant, b);
}

void DomSolver::takeSourcesShape(cl::CommandQueue& queue) {
    SourcesShape& s = *sourcesShape_;
    std::vector<glm::vec4> zero(s.voxels);
    const int slot = pool_->acquire(queue, 0, 1u << kSource | 1u << kFlux);
    cl::Buffer& source = pool_->buffer(slot, kSource);
    if (s.voxels > 0) {
        gatherZero_.setArg(0, source);
        gatherZero_.setArg(1, s.at);
        gatherZero_.setArg(2, s.gathered);
        queue.enqueueNDRangeKernel(gatherZero_, cl::NullRange, cl::NDRange(s.voxels));
        queue.enqueueReadBuffer(s.gathered, CL_TRUE, 0, s.voxels * sizeof(glm::vec4), zero.data());
    }
    Rgb sum(0.0);
    for (const glm::vec4& z : zero)
        for (int c = 0; c < 3; ++c) sum[c] += z[c];
    if (halo_) {
        if (!s.summed) halo_->sum(&s.total[0], 3);
        halo_->sum(&sum[0], 3);
    }
    s.summed = true;
    cl_float4 c{};
    for (int i = 0; i < 3; ++i) c.s[i] = s.total[i] > 0.0 ? float(sum[i] / s.total[i]) : 0.0f;
    if (s.voxels > 0) {
        takeShape_.setArg(0, source);
        takeShape_.setArg(1, s.at);
        takeShape_.setArg(2, s.shape);
        takeShape_.setArg(3, c);
        queue.enqueueNDRangeKernel(takeShape_, cl::NullRange, cl::NDRange(s.voxels));
    }
    add_.setArg(0, pool_->buffer(slot, kFlux));
    add_.setArg(1, s.flux);
    add_.setArg(2, c);
    queue.enqueueNDRangeKernel(add_, cl::NullRange, cl::NDRange(tiling_.voxels(0)));
    pool_->written(slot, 1u << kSource | 1u << kFlux);
}

Rgb DomSolver::iterate(cl::CommandQueue& queue) {
    if (sourcesShape_) takeSourcesShape(queue);
    sweep_.setArg(5, boundary_[swaps_ % 2]);
    sweep_.setArg(6, boundary_[(swaps_ + 1) % 2]);
    sweep_.setArg(17, mirror_[swaps_ % 2]);
    sweep_.setArg(18, mirror_[(swaps_ + 1) % 2]);
    for (int octant = 0; octant < 8; ++octant) {
        sweep_.setArg(12, cl_int(octant));
        // The blocks wavefront by wavefront (thesis 5.3.4: the loading order is known before the sweep).
        for (const std::vector<int>& wavefront : order_[octant]) {
            pool_->newWavefront();
            for (const int b : wavefront) sweepBlock(queue, octant, b);
        }
    }
    ++swaps_;
    Rgb power = scatterGeneration(queue);
    if (halo_) halo_->sum(&power[0], 3);
    return power;
}

void DomSolver::addTail(cl::CommandQueue& queue, const Rgb& factor) {
    add_.setArg(2, cl_float4{{float(factor.r), float(factor.g), float(factor.b), 0.0f}});
    for (int b = 0; b < tiling_.blocks(); ++b) {
        pool_->newWavefront();
        const int slot = pool_->acquire(queue, b, 1u << kTotal | 1u << kLastFlux);
        add_.setArg(0, pool_->buffer(slot, kTotal));
        add_.setArg(1, pool_->buffer(slot, kLastFlux));
        queue.enqueueNDRangeKernel(add_, cl::NullRange, cl::NDRange(tiling_.voxels(b)));
        pool_->written(slot, 1u << kTotal);
    }
}

bool DomSolver::step(cl::CommandQueue& queue, double tolerance) {
    if (run_.converged) return false;
    if (uncollidedPower_) {
        if (halo_) halo_->sum(&(*uncollidedPower_)[0], 3);
        total_power_ += *uncollidedPower_;
        previous_power_ = *uncollidedPower_;
        uncollidedPower_.reset();
    }
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
    std::vector<glm::vec4> out(grid_.count() * moments_);
    if (tiling_.blocks() == 1) {
        pool_->get(queue, 0, kTotal, out.data());
        return out;
    }
    std::vector<glm::vec4> block;
    for (int b = 0; b < tiling_.blocks(); ++b) {
        block.resize(tiling_.voxels(b) * moments_);
        pool_->get(queue, b, kTotal, block.data());
        putBox(out, grid_.dims, tiling_.lo(b), tiling_.hi(b), block, size_t(moments_));
    }
    return out;
}

std::vector<glm::vec4> DomSolver::boundaryRadiance(cl::CommandQueue& queue) {
    if (tiling_.blocks() > 1) throw Error("internal: the box's boundary radiance of a pooled solver");
    std::vector<glm::vec4> out(faceOffset(6, grid_.dims, 8 * ordinates_.perOctant));
    queue.enqueueReadBuffer(boundary_[swaps_ % 2], CL_TRUE, 0, out.size() * sizeof(glm::vec4), out.data());
    return out;
}

}  // namespace lucent::hybrid
