#include "hybrid/mdom_scattering.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>

#include <tbb/parallel_for.h>

#include "core/error.h"
#include "core/refraction.h"
#include "core/spherical_harmonics.h"
#include "core/stopwatch.h"
#include "hybrid/internal/cl_device.h"
#include "hybrid/internal/dom_solver.h"
#include "hybrid/internal/sweep_halo.h"
#include "hybrid/ordinates.h"
#include "hybrid/voxelisation.h"

namespace lucent::hybrid {

struct MdomScattering::Impl {
    ClDevice device;
    cl::Program direct = device.build({"dom_direct.cl"});
};

MdomScattering::MdomScattering() : impl_(std::make_unique<Impl>()) {}
MdomScattering::~MdomScattering() = default;
std::string MdomScattering::deviceName() const { return impl_->device.name(); }

size_t MdomScattering::bytesFor(const std::array<int, 3>& dims, int directions, int bands, double devicePool) {
    // The solver's buffers, and the direct pass's: two extinctions, two results, the blockers.
    const size_t voxels = GridIndex{dims}.count();
    return DomSolver::bytesFor(dims, directions, bands, false, DomPool(devicePool)) +
           voxels * (4 * sizeof(glm::vec4) + sizeof(cl_int));
}

size_t MdomScattering::poolHostBytes(const std::array<int, 3>& dims, int bands, double devicePool, bool refracts) {
    return DomSolver::hostBytesFor(dims, bands, DomPool(devicePool), refracts);
}

ScatteringGrid MdomSolution::towards(const Vec3& eye) const {
    ScatteringGrid g;
    g.bounds = bounds;
    g.dims = dims;
    const GridIndex index{dims};
    const size_t voxels = index.count();
    const int m = bands * bands;
    g.source.assign(3 * voxels, 0.0f);
    g.extinction.resize(3 * voxels);
    g.ior = ior;
    g.refraction = refraction;
    const Vec3 voxel = bounds.extent() / Vec3(dims[0], dims[1], dims[2]);
    std::vector<double> y(m), gl(m);
    for (int i = 0; i < m; ++i) gl[i] = std::pow(this->g, int(std::sqrt(double(i))));
    for (int k = 0; k < dims[2]; ++k)
        for (int j = 0; j < dims[1]; ++j)
            for (int i = 0; i < dims[0]; ++i) {
                const size_t v = index(i, j, k);
                for (int c = 0; c < 3; ++c) g.extinction[3 * v + c] = extinction[v][c];
                if (scattering[v] == glm::vec4(0.0f)) continue;
                const Vec3 toEye = eye - (bounds.min + voxel * Vec3(i + 0.5, j + 0.5, k + 0.5));
                evaluateSh(bands, glm::length(toEye) > 0.0 ? glm::normalize(toEye) : Vec3(0, 0, 1), y);
                const Vec3 centre = bounds.min + voxel * Vec3(i + 0.5, j + 0.5, k + 0.5);
                Rgb peak(0.0);
                for (const Peak& p : peaks) {
                    const Vec3 w = p.travelAt(v, centre);
                    if (!(glm::length(w) > 0.0) || !(glm::length(toEye) > 0.0)) continue;
                    const double phase = henyeyGreenstein(glm::dot(glm::normalize(w), glm::normalize(toEye)), this->g);
                    peak += phase * Rgb(p.excess[v].r, p.excess[v].g, p.excess[v].b);
                }
                for (int c = 0; c < 3; ++c) {
                    double s = 0.0;
                    for (int n = 0; n < m; ++n) s += gl[n] * double(moments[v * m + n][c]) * y[n];
                    // The truncated expansion can dip below zero where the light is strongly directional.
                    g.source[3 * v + c] = float(double(scattering[v][c]) * (std::max(0.0, s) + peak[c]));
                }
            }
    return g;
}

struct MdomProgress::Impl {
    ClDevice& device;
    MdomSettings settings;
    std::string what;
    MdomStats stats;
    MdomSolution solution;  // all but the moments
    SweepPartition part;    // this rank's share of the voxels (all of them alone)
    std::optional<SweepHalo> halo;
    std::unique_ptr<DomSolver> solver;

    const Peers* shared() const { return settings.peers && settings.peers->size() > 1 ? settings.peers : nullptr; }
    // A device failure; during shared sweeps the other ranks may wait for this one, so it ends the job.
    [[noreturn]] void fail(const cl::Error& e) const {
        const std::string why =
            "OpenCL device '" + device.name() + "': " + e.what() + " failed for " + what + ": " + clErrorText(e.err());
        if (shared()) shared()->abort(why);
        throw Error(why);
    }
};

MdomProgress::MdomProgress(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
MdomProgress::~MdomProgress() = default;
const MdomStats& MdomProgress::stats() const { return impl_->stats; }

bool MdomProgress::iterate() {
    Impl& p = *impl_;
    if (p.stats.converged || p.stats.iterations >= p.settings.maxIterations) return false;
    const Stopwatch stopwatch;
    try {
        p.solver->step(p.device.marchQueue, p.settings.tolerance);
    } catch (const cl::Error& e) {
        p.fail(e);
    }
    const DomSolver::Run& run = p.solver->progress();
    p.stats.iterations = run.iterations;
    p.stats.converged = run.converged;
    p.stats.ratio = run.ratio;
    p.stats.sweepSeconds += stopwatch.seconds();
    p.stats.bytesToDevice = p.solver->traffic().bytesUp;
    p.stats.bytesFromDevice = p.solver->traffic().bytesDown;
    return !p.stats.converged && p.stats.iterations < p.settings.maxIterations;
}

MdomSolution MdomProgress::solution() const {
    MdomSolution s = impl_->solution;
    try {
        s.moments = impl_->solver->totalFlux(impl_->device.marchQueue);
    } catch (const cl::Error& e) {
        impl_->fail(e);
    }
    if (const Peers* peers = impl_->shared())
        s.moments = gatherShares(s.dims, std::move(s.moments), size_t(s.bands) * s.bands, *peers);
    return s;
}

MdomSolution MdomScattering::solve(const VolumeObject& object, const std::vector<Light>& lights, const MdomSettings& s,
                                   MdomStats* stats, const IterationCallback& afterIteration) {
    const std::unique_ptr<MdomProgress> progress = begin(object, lights, s);
    for (bool more = true; more;) {
        more = progress->iterate();
        if (afterIteration && progress->stats().iterations > 0)
            afterIteration(progress->stats().iterations - 1, progress->solution());
    }
    if (stats) *stats = progress->stats();
    return progress->solution();
}

namespace {

// The medium as the sweeps see it, delta-M scaled (thesis 5.3.2):
// sigma_t* = sigma_t - f sigma_s, sigma_s* = (1 - f) sigma_s; beside it the true
// extinction the view and the forward peak need, and the blockers' voxels.
struct MdomMaterials {
    DomGrid grid;
    std::vector<glm::vec4> trueExtinction;
    std::vector<cl_int> opaque;
};

MdomMaterials materialsOf(const Voxelisation& vox, const MediumDesc& medium, const DeltaM& dm) {
    const GridShape& shape = vox.shape;
    const size_t voxels = shape.count();
    MdomMaterials out;
    DomGrid& grid = out.grid;
    grid.dims = shape.dims;
    grid.edges = Vec3(shape.voxel);
    grid.extinction.assign(voxels, glm::vec4(0.0f));
    grid.scattering.assign(voxels, glm::vec4(0.0f));
    grid.phase.assign(voxels, glm::vec4(float(medium.g), 0.0f, 0.0f, 0.0f));
    grid.ior = medium.ior;
    if (vox.refracting) {
        // The outward normal: down the smoothed index's gradient.
        grid.boundaryNormal.resize(voxels);
        for (size_t v = 0; v < voxels; ++v) {
            const glm::vec3 g(vox.refraction[v].y, vox.refraction[v].z, vox.refraction[v].w);
            grid.boundaryNormal[v] = glm::length(g) > 0.0f ? -glm::normalize(g) : glm::vec3(0.0f);
        }
    }
    out.trueExtinction.assign(voxels, glm::vec4(0.0f));
    out.opaque.assign(voxels, 0);
    for (size_t v = 0; v < voxels; ++v) {
        const glm::vec4& m = vox.material[v];
        if (m.a == kOpaque) {
            // A blocker absorbs what reaches it: optically thick, not scattering.
            out.opaque[v] = 1;
            grid.extinction[v] = glm::vec4(glm::vec3(float(1e4 / shape.voxel)), 0.0f);
            continue;
        }
        if (!(m.a > 0.0f)) continue;
        for (int c = 0; c < 3; ++c) {
            const double sigmaS = medium.albedo[c] * m[c];
            grid.extinction[v][c] = float(m[c] - dm.f * sigmaS);
            grid.scattering[v][c] = float((1.0 - dm.f) * sigmaS);
            out.trueExtinction[v][c] = m[c];
        }
        grid.extinction[v].a = grid.scattering[v] != glm::vec4(0.0f) ? 1.0f : 0.0f;  // only scattering voxels
    }
    return out;
}

// The direct component, light by light (thesis 5.3.1): each light's uncollided
// irradiance through the scaled and the true medium, giving the first source
// Q_lm = sigma_s* g*_l E* Y_lm(omega_light) and the forward peak (E* - E),
// which the sweeps cannot carry and the view adds back.
struct DirectComponent {
    std::vector<glm::vec4> source;  // [voxel][moment]
    std::vector<MdomSolution::Peak> peaks;
};

// One light's irradiance per voxel, through the scaled and the true extinction.
struct LightArrival {
    std::vector<glm::vec4> scaled, unscaled;
    std::vector<glm::vec3> travel;  // the direction the light travels at each voxel (empty: from the light)
};

// Straight from the light, marched on the device (dom_direct.cl).
class StraightArrivals {
public:
    StraightArrivals(ClDevice& device, const cl::Program& program, const GridShape& shape,
                     const MdomMaterials& materials)
        : queue_(device.marchQueue), voxels_(shape.count()), kernel_(program, "dom_uncollided") {
        const cl::Context& cx = device.context;
        // CL_MEM_COPY_HOST_PTR copies from the host pointer and never writes it.
        scaled_ = cl::Buffer(cx, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, voxels_ * sizeof(glm::vec4),
                             const_cast<glm::vec4*>(materials.grid.extinction.data()));
        true_ = cl::Buffer(cx, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, voxels_ * sizeof(glm::vec4),
                           const_cast<glm::vec4*>(materials.trueExtinction.data()));
        opaque_ = cl::Buffer(cx, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, voxels_ * sizeof(cl_int),
                             const_cast<cl_int*>(materials.opaque.data()));
        scaledOut_ = cl::Buffer(cx, CL_MEM_WRITE_ONLY, voxels_ * sizeof(glm::vec4));
        trueOut_ = cl::Buffer(cx, CL_MEM_WRITE_ONLY, voxels_ * sizeof(glm::vec4));
        kernel_.setArg(0, scaled_);
        kernel_.setArg(1, true_);
        kernel_.setArg(2, opaque_);
        kernel_.setArg(3, scaledOut_);
        kernel_.setArg(4, trueOut_);
        kernel_.setArg(8, float4Of(shape.origin, 0.0));
        kernel_.setArg(9, float(shape.voxel));
        kernel_.setArg(10, cl_int4{{shape.dims[0], shape.dims[1], shape.dims[2], 0}});
    }

    LightArrival of(const Light& light) {
        const bool point = light.type == Light::Type::Point;
        kernel_.setArg(5, point ? float4Of(light.position, 1.0) : float4Of(light.direction, 0.0));
        kernel_.setArg(6, float4Of(light.power, light.radius));
        const glm::dvec4 cone = spotCoefficients(light);
        kernel_.setArg(7, float4Of(Vec3(cone), cone.w));
        queue_.enqueueNDRangeKernel(kernel_, cl::NullRange, cl::NDRange(voxels_));
        LightArrival a{std::vector<glm::vec4>(voxels_), std::vector<glm::vec4>(voxels_), {}};
        queue_.enqueueReadBuffer(scaledOut_, CL_TRUE, 0, voxels_ * sizeof(glm::vec4), a.scaled.data());
        queue_.enqueueReadBuffer(trueOut_, CL_TRUE, 0, voxels_ * sizeof(glm::vec4), a.unscaled.data());
        return a;
    }

private:
    cl::CommandQueue& queue_;
    size_t voxels_;
    cl::Kernel kernel_;
    cl::Buffer scaled_, true_, opaque_, scaledOut_, trueOut_;
};

// Through a refracting boundary, on the CPU: per voxel the light's way found
// by the Newton solve the ground truths and ss use (core/refraction.h), its
// Fresnel transmission and the bundle's focusing, then marched inside along it.
LightArrival refractedArrival(const VolumeObject& object, const GridShape& shape, const MdomMaterials& materials,
                              const Light& light) {
    const size_t voxels = shape.count();
    LightArrival a{std::vector<glm::vec4>(voxels, glm::vec4(0.0f)), std::vector<glm::vec4>(voxels, glm::vec4(0.0f)),
                   std::vector<glm::vec3>(voxels, glm::vec3(0.0f))};
    const GridIndex index = shape.index();
    object.boundary();  // built once here, not raced for by the voxels
    tbb::parallel_for(0, shape.dims[2], [&](int k) {
        for (int j = 0; j < shape.dims[1]; ++j)
            for (int i = 0; i < shape.dims[0]; ++i) {
                const size_t v = index(i, j, k);
                if (materials.trueExtinction[v] == glm::vec4(0.0f) || materials.opaque[v]) continue;
                const Vec3 x = shape.centre(i, j, k);
                const std::optional<RefractedArrival> arrival = lightThroughBoundary(object, light, x);
                if (!arrival) continue;
                const int steps = std::max(1, int(std::ceil(arrival->inside / (0.5 * shape.voxel))));
                const double dt = arrival->inside / steps;
                glm::dvec3 tauScaled(0.0), tauTrue(0.0);
                bool blocked = false;
                for (int s = 0; s < steps && !blocked; ++s) {
                    const Vec3 q = (x + (s + 0.5) * dt * arrival->toLight - shape.origin) / shape.voxel;
                    const std::array<int, 3> c{std::clamp(int(std::floor(q.x)), 0, shape.dims[0] - 1),
                                               std::clamp(int(std::floor(q.y)), 0, shape.dims[1] - 1),
                                               std::clamp(int(std::floor(q.z)), 0, shape.dims[2] - 1)};
                    const size_t at = index(c);
                    blocked = materials.opaque[at] != 0;
                    tauScaled += glm::dvec3(glm::vec3(materials.grid.extinction[at])) * dt;
                    tauTrue += glm::dvec3(glm::vec3(materials.trueExtinction[at])) * dt;
                }
                if (blocked) continue;
                const glm::dvec3 e(arrival->irradiance);
                a.scaled[v] = glm::vec4(glm::vec3(e * glm::exp(-tauScaled)), 0.0f);
                a.unscaled[v] = glm::vec4(glm::vec3(e * glm::exp(-tauTrue)), 0.0f);
                a.travel[v] = glm::vec3(-arrival->toLight);
            }
    });
    return a;
}

DirectComponent directComponent(ClDevice& device, const cl::Program& program, const VolumeObject& object,
                                const GridShape& shape, const MdomMaterials& materials,
                                const std::vector<Light>& lights, const DeltaM& dm, int bands) {
    const size_t voxels = shape.count();
    const int moments = bands * bands;
    const bool refracting = object.desc().medium.ior != 1.0;
    DirectComponent out{std::vector<glm::vec4>(voxels * moments, glm::vec4(0.0f)), {}};
    std::optional<StraightArrivals> straight;
    if (!refracting) straight.emplace(device, program, shape, materials);
    std::vector<double> y(moments);
    const std::vector<glm::vec4>& scattering = materials.grid.scattering;
    for (const Light& light : lights) {
        const LightArrival a = refracting ? refractedArrival(object, shape, materials, light) : straight->of(light);
        MdomSolution::Peak peak{light, std::vector<glm::vec4>(voxels), a.travel};
        for (size_t v = 0; v < voxels; ++v) peak.excess[v] = glm::max(a.scaled[v] - a.unscaled[v], glm::vec4(0.0f));
        out.peaks.push_back(std::move(peak));
        for (int kz = 0; kz < shape.dims[2]; ++kz)
            for (int ky = 0; ky < shape.dims[1]; ++ky)
                for (int kx = 0; kx < shape.dims[0]; ++kx) {
                    const size_t v = shape.index()(kx, ky, kz);
                    if (a.scaled[v] == glm::vec4(0.0f) && a.unscaled[v] == glm::vec4(0.0f)) continue;
                    const Vec3 w = out.peaks.back().travelAt(v, shape.centre(kx, ky, kz));
                    if (glm::length(w) <= 0.0) continue;
                    evaluateSh(bands, glm::normalize(w), y);
                    for (int m = 0; m < moments; ++m) {
                        const int l = int(std::sqrt(double(m)));
                        out.source[v * moments + m] += scattering[v] * a.scaled[v] * float(dm.moments[l] * y[m]);
                    }
                }
    }
    return out;
}

}  // namespace

namespace {

// Checks that the solve fits, and where the pool's blocks live: blocks that do
// not fit in the memory left spill to an unnamed file in the temporary
// directory (TMPDIR). The host keeps the source it uploads and the moments it
// reads back (M float4 each per voxel) and the materials (4 float4): 3.78 GB
// peak measured at 128^3, M = 16, against the device's 2.35 GB.
DomPool poolFor(const ClDevice& device, const GridShape& shape, const MdomSettings& s, bool refracts,
                const std::string& what, MdomStats& stats) {
    DomPool pool(s.devicePool);
    const size_t deviceBytes = MdomScattering::bytesFor(shape.dims, s.directions, s.bands, s.devicePool);
    const size_t hostBytes = shape.count() * size_t(2 * s.bands * s.bands + 4) * sizeof(glm::vec4);
    const size_t blockBytes = DomSolver::hostBytesFor(shape.dims, s.bands, pool, refracts);
    const size_t needed = hostBytes + blockBytes + (device.sharesHostMemory() ? deviceBytes : 0);
    if (blockBytes > 0 && needed > ClDevice::hostMemoryAvailable(needed)) {
        std::error_code error;
        pool.spillTo = std::filesystem::temp_directory_path(error);
        if (error)
            throw Error(
                "the device pool's blocks do not fit in memory, and there is no temporary directory to "
                "spill them to: " +
                error.message());
    }
    device.checkMemory(deviceBytes, DomSolver::largestBufferFor(shape.dims, s.bands, pool), what,
                       hostBytes + (pool.spillTo.empty() ? blockBytes : 0));
    stats.poolSlots = DomSolver::slotsFor(shape.dims, pool);
    stats.poolBlocks = DomSolver::pooled(shape.dims, pool) ? BlockTiling(shape.dims, pool.edge).blocks() : 1;
    stats.spilled = !pool.spillTo.empty();
    return pool;
}

// A rank's share of the grid, with the inner boundary found on the whole grid
// (a face on the share's border belongs to the voxel with medium beside it,
// which sweeps its reflection on this rank or the next).
DomGrid shareOf(const DomGrid& whole, const SweepPartition& part) {
    const DomSolver::InnerBoundary inner = DomSolver::innerBoundary(whole);
    DomGrid share;
    share.dims = part.dims();
    share.edges = whole.edges;
    share.ior = whole.ior;
    share.extinction = boxOf(whole.extinction, whole.dims, part.lo, part.hi);
    share.scattering = boxOf(whole.scattering, whole.dims, part.lo, part.hi);
    share.phase = boxOf(whole.phase, whole.dims, part.lo, part.hi);
    if (!whole.boundaryNormal.empty()) share.boundaryNormal = boxOf(whole.boundaryNormal, whole.dims, part.lo, part.hi);
    if (!inner.normals.empty()) {
        share.innerFace = boxOf(inner.faces, whole.dims, part.lo, part.hi, 6);
        share.faceNormal = inner.normals;
    }
    return share;
}

}  // namespace

std::unique_ptr<MdomProgress> MdomScattering::begin(const VolumeObject& object, const std::vector<Light>& lights,
                                                    const MdomSettings& s) {
    if (!s.peers || s.peers->size() == 1) return prepare(object, lights, s);
    // Shared with the ranks of an MPI job: they agree before they first talk,
    // so that a rank that failed leaves none waiting for it.
    std::unique_ptr<MdomProgress> progress;
    std::string failure;
    try {
        progress = prepare(object, lights, s);
    } catch (const Error& e) {
        failure = e.what();
    } catch (const std::bad_alloc&) {
        failure = "out of memory for " + object.desc().name;
    }
    double failed = failure.empty() ? 0.0 : 1.0;
    s.peers->sum(&failed, 1);
    if (!failure.empty()) throw Error(failure);
    if (failed > 0.0) throw PeerFailed{};
    return progress;
}

std::unique_ptr<MdomProgress> MdomScattering::prepare(const VolumeObject& object, const std::vector<Light>& lights,
                                                      const MdomSettings& s) {
    ClDevice& device = impl_->device;
    Stopwatch stopwatch;
    const GridShape shape = gridShapeFor(object.mesh().bounds(), s.resolution);
    const std::string what = shape.describe(object.desc().name);
    auto progress = std::make_unique<MdomProgress::Impl>(MdomProgress::Impl{device, s, what, {}, {}, {}, {}, {}});
    MdomStats& stats = progress->stats;
    stats.device = device.name();
    const int ranks = progress->shared() ? s.peers->size() : 1;
    progress->part = partitionSweeps(shape.dims, ranks > 1 ? s.peers->rank() : 0, ranks);
    const DomPool pool = poolFor(device, shape, s, object.desc().medium.ior != 1.0, what, stats);
    if (ranks > 1 && DomSolver::pooled(shape.dims, pool))
        throw Error(
            "--device-pool does not yet combine with MPI ranks: each rank's share of the voxels is swept "
            "whole on its device (docs/mdom.md)");
    const Voxelisation vox = voxelise(object, s.resolution);
    stats.voxeliseSeconds = stopwatch.seconds();
    stopwatch.restart();

    const MediumDesc& medium = object.desc().medium;
    const DeltaM dm = deltaM(medium.g, s.bands);
    MdomMaterials materials = materialsOf(vox, medium, dm);
    try {
        DirectComponent direct = directComponent(device, impl_->direct, object, shape, materials, lights, dm, s.bands);
        stats.directSeconds = stopwatch.seconds();
        MdomSolution& solution = progress->solution;
        solution.bounds = shape.bounds();
        solution.dims = shape.dims;
        solution.bands = s.bands;
        solution.g = medium.g;
        solution.extinction = std::move(materials.trueExtinction);
        solution.scattering.resize(shape.count());
        for (size_t v = 0; v < shape.count(); ++v)
            solution.scattering[v] = materials.opaque[v]
                                         ? glm::vec4(0.0f)
                                         : solution.extinction[v] * glm::vec4(glm::vec3(medium.albedo), 0.0f);
        solution.peaks = std::move(direct.peaks);
        solution.refraction = vox.viewRefraction();
        solution.ior = vox.ior;
        if (ranks == 1) {
            progress->solver = std::make_unique<DomSolver>(device, materials.grid, s.directions, s.bands,
                                                           BoundaryFlags{}, nullptr, pool);
            progress->solver->setSource(device.marchQueue, direct.source);
        } else {
            const SweepPartition& part = progress->part;
            progress->halo.emplace(*s.peers, part, s.directions);
            progress->solver = std::make_unique<DomSolver>(device, shareOf(materials.grid, part), s.directions, s.bands,
                                                           BoundaryFlags{}, &*progress->halo);
            progress->solver->setSource(device.marchQueue,
                                        boxOf(direct.source, shape.dims, part.lo, part.hi, size_t(s.bands) * s.bands));
        }
        return std::unique_ptr<MdomProgress>(new MdomProgress(std::move(progress)));
    } catch (const cl::Error& e) {
        throw Error("OpenCL device '" + device.name() + "': " + e.what() + " failed for " + what + ": " +
                    clErrorText(e.err()));
    }
}

}  // namespace lucent::hybrid
