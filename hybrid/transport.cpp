#include "hybrid/transport.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>

#include "core/error.h"
#include "core/stopwatch.h"
#include "hybrid/internal/dom_solver.h"
#include "hybrid/internal/sweep_halo.h"
#include "hybrid/internal/uncollided_flux.h"
#include "hybrid/ordinates.h"

namespace lucent::hybrid {

namespace {

// The far field's traversal steps: a budget that keeps the far field to seconds
// on a 2-core machine (docs/transport.md).
constexpr double kMarchBudget = 2.5e9;
// Cells longer than this many times the shortest would need too many near kernels.
constexpr double kMostAspect = 4.0;

// Why the uncollided flux cannot be integrated cell to cell here, or "" when it can.
std::string whyNotMarched(const TransportProblem& p, const DomGrid& grid, size_t sourceCells) {
    static const char* const axes[3] = {"x", "y", "z"};
    for (int a = 0; a < 3; ++a)
        if (p.reflective[2 * a] && p.reflective[2 * a + 1])
            return std::string("both ") + axes[a] +
                   " faces are reflective, so the sources' mirror images repeat without end; the uncollided flux "
                   "is swept";
    const double longest = std::max({grid.edges.x, grid.edges.y, grid.edges.z}),
                 shortest = std::min({grid.edges.x, grid.edges.y, grid.edges.z});
    if (longest > kMostAspect * shortest)
        return "cells more than " + std::to_string(int(kMostAspect)) +
               " times longer on one axis than on another; the uncollided flux is swept";
    const size_t images = size_t(mirrorImages(p.reflective));
    if (sourceCells * images > kMostMarchedSources)
        return std::to_string(sourceCells) + " source cells" +
               (images > 1 ? " and their mirror images, " + std::to_string(sourceCells * images) + " in all," : "") +
               " are more than the " + std::to_string(kMostMarchedSources) +
               " it is integrated for; the uncollided flux is swept";
    return "";
}

// Why auto does not march here though it could: the far field would take long.
std::string whyNotAuto(const TransportProblem& p, const DomGrid& grid, const std::vector<double>& density,
                       size_t sourceCells) {
    const double work = uncollidedFluxWork(grid, density, p.reflective);
    if (work <= kMarchBudget) return "";
    const int images = mirrorImages(p.reflective);
    return std::to_string(sourceCells) + " source cells" +
           (images > 1 ? " and their " + std::to_string(images - 1) + " mirror images each" : std::string()) + " in " +
           std::to_string(grid.count()) +
           " cells are too many to integrate cell to cell in about 10 s; the uncollided flux is swept (\"marched\" "
           "asks for it all the same)";
}

// The problem's materials in the cells [lo, hi) of its grid.
struct Materials {
    DomGrid grid;
    std::vector<glm::vec4> source;  // [cell][M] radiance moments per unit length
    std::vector<double> density;    // particles per unit volume per unit time
};

Materials materialsIn(const TransportProblem& p, const std::array<int, 3>& lo, const std::array<int, 3>& hi) {
    Materials m;
    m.grid.dims = {hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]};
    m.grid.edges = p.domain.extent() / Vec3(p.cells[0], p.cells[1], p.cells[2]);
    const size_t count = m.grid.count();
    const int moments = p.bands * p.bands;
    m.grid.extinction.assign(count,
                             glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));  // a flux wanted everywhere: points may lie in vacuum
    m.grid.scattering.assign(count, glm::vec4(0.0f));
    m.grid.phase.assign(count, glm::vec4(0.0f));
    m.source.assign(count * moments, glm::vec4(0.0f));
    m.density.assign(count, 0.0);
    const GridIndex index = m.grid.index();
    // Cells belong to the last region holding their centre; the rest are vacuum.
    for (int k = lo[2]; k < hi[2]; ++k)
        for (int j = lo[1]; j < hi[1]; ++j)
            for (int i = lo[0]; i < hi[0]; ++i) {
                const Vec3 centre = p.domain.min + m.grid.edges * Vec3(i + 0.5, j + 0.5, k + 0.5);
                const TransportRegion* in = nullptr;
                for (const TransportRegion& r : p.regions)
                    if (r.box.contains(centre)) in = &r;
                if (!in) continue;
                const size_t v = index(i - lo[0], j - lo[1], k - lo[2]);
                const DeltaM dm = deltaM(in->g, p.bands);
                m.grid.extinction[v] = glm::vec4(glm::vec3(float(in->sigmaT - dm.f * in->sigmaS)), 1.0f);
                m.grid.scattering[v] = glm::vec4(glm::vec3(float((1.0 - dm.f) * in->sigmaS)), 0.0f);
                m.grid.phase[v] = glm::vec4(float(in->g), 0.0f, 0.0f, 0.0f);
                // An isotropic emission q / (4 pi) per unit length: its zero moment is q / sqrt(4 pi).
                m.source[v * moments] = glm::vec4(glm::vec3(float(in->source / std::sqrt(4.0 * kPi))), 0.0f);
                m.density[v] = in->source;
            }
    return m;
}

// Whether the uncollided flux is marched, and why not where auto sweeps it.
void decideUncollided(const TransportProblem& p, const Materials& whole, TransportResult& r) {
    const size_t sourceCells =
        size_t(std::count_if(whole.density.begin(), whole.density.end(), [](double q) { return q > 0.0; }));
    std::string whyNot = sourceCells == 0 ? "" : whyNotMarched(p, whole.grid, sourceCells);
    if (p.uncollided == TransportProblem::Uncollided::Marched && !whyNot.empty())
        throw Error(p.file.string() +
                    ": /solver/uncollided: cannot be \"marched\": " + whyNot.substr(0, whyNot.find(';')));
    if (p.uncollided == TransportProblem::Uncollided::Auto && whyNot.empty() && sourceCells > 0)
        whyNot = whyNotAuto(p, whole.grid, whole.density, sourceCells);
    r.uncollidedMarched = p.uncollided != TransportProblem::Uncollided::Swept && whyNot.empty() && sourceCells > 0;
    if (p.uncollided == TransportProblem::Uncollided::Auto) r.uncollidedWhy = whyNot;
}

// Every rank's zero moments into rank 0's grid of the whole problem, phi = sqrt(4 pi) phi_00.
std::vector<float> gatherFlux(const TransportProblem& p, const std::vector<glm::vec4>& flux, int moments,
                              const SweepPartition& part, const Peers* peers) {
    std::vector<glm::vec4> mine(GridIndex{part.dims()}.count());
    for (size_t v = 0; v < mine.size(); ++v) mine[v].r = float(double(flux[v * moments].r) * std::sqrt(4.0 * kPi));
    if (peers) mine = gatherShares(p.cells, std::move(mine), 1, *peers);
    std::vector<float> out(mine.size());
    for (size_t v = 0; v < mine.size(); ++v) out[v] = mine[v].r;
    return out;
}

}  // namespace

TransportFootprint transportFootprint(const std::array<int, 3>& cells, int directions, int bands, int ranks,
                                      bool whole) {
    TransportFootprint f;
    const SweepPartition part = partitionSweeps(cells, 0, ranks);  // rank 0's share: the largest
    f.processGrid = part.ranks;
    const std::array<int, 3> d = part.dims();
    const double mine = double(d[0]) * d[1] * d[2], all = double(cells[0]) * cells[1] * cells[2];
    const int moments = bands * bands;
    // Marched, the uncollided flux stays on the device for the first-collided source.
    f.deviceBytes = double(DomSolver::bytesFor(d, directions, bands, ranks > 1)) +
                    (whole ? double(DomSolver::largestBufferFor(d, bands)) : 0.0);
    // Materials (three float4, the source's moments, the density) and the flux read back.
    const double perCell = (3 + moments) * 16.0 + 8.0;
    f.hostBytes = mine * (perCell + 16.0 * moments) + (whole && ranks > 1 ? all * perCell : 0.0);
    // Each octant's K directions cross each face between ranks once: N per face cell.
    const double faces =
        double(cells[2]) * (double(cells[1]) * (part.ranks[0] - 1) + double(cells[0]) * (part.ranks[1] - 1));
    f.haloBytesPerIteration = faces * directions * 16.0;
    f.pipelineStages = part.ranks[0] + part.ranks[1] - 2;
    f.blocks = sweepBlocks(part);
    return f;
}

struct TransportSolver::Impl {
    const TransportProblem& p;
    const Peers* peers;
    Stopwatch stopwatch;
    SweepPartition part;
    ClDevice device;
    std::string what;
    TransportResult r;
    std::optional<SweepHalo> halo;
    std::optional<DomSolver> solver;

    Impl(const TransportProblem& problem, const Peers* with)
        : p(problem), peers(with), part(partitionSweeps(p.cells, rank(), ranks())) {}
    int ranks() const { return peers ? peers->size() : 1; }
    int rank() const { return peers ? peers->rank() : 0; }
    void prepare();
    void sweep();
};

// Everything before the ranks first talk: the device, the materials, the source.
void TransportSolver::Impl::prepare() {
    const std::array<int, 3> dims = part.dims();
    const size_t count = size_t(dims[0]) * dims[1] * dims[2];
    what = "the " + std::to_string(dims[0]) + "x" + std::to_string(dims[1]) + "x" + std::to_string(dims[2]) +
           " cells of " + p.file.string();
    // The device: the sweeps' buffers and, unless swept, the uncollided flux
    // (the first-collided source keeps it). The host's copies: the source and
    // the flux read back (M float4 per cell), the materials.
    const bool marchable = p.uncollided != TransportProblem::Uncollided::Swept;
    device.checkMemory(DomSolver::bytesFor(dims, p.directions, p.bands, ranks() > 1) +
                           (marchable ? DomSolver::largestBufferFor(dims, p.bands) : 0),
                       DomSolver::largestBufferFor(dims, p.bands), what,
                       count * size_t(2 * p.bands * p.bands + 3) * sizeof(glm::vec4));
    // The first-collision source of a rank's cells sees every source through
    // the whole grid: each rank holds all of it unless the uncollided flux is swept.
    const bool wholeNeeded = ranks() == 1 || marchable;
    const Materials whole = wholeNeeded ? materialsIn(p, {0, 0, 0}, p.cells) : Materials{};
    const Materials local = ranks() == 1 ? Materials{} : materialsIn(p, part.lo, part.hi);
    const Materials& mine = ranks() == 1 ? whole : local;
    if (wholeNeeded) decideUncollided(p, whole, r);  // swept: nothing to decide
    BoundaryFlags reflective = p.reflective;
    for (int f = 0; f < 6; ++f) reflective[f] = reflective[f] && part.neighbour[f] < 0;  // inside: a neighbour's
    if (ranks() > 1) halo.emplace(*peers, part, p.directions);
    solver.emplace(device, mine.grid, p.directions, p.bands, reflective, halo ? &*halo : nullptr);
    if (r.uncollidedMarched)  // the first-collision source: generation zero integrated, the sweeps carry the rest
        solver->setUncollidedFlux(device.marchQueue,
                                  uncollidedFlux(whole.grid, whole.density, p.bands, p.reflective, part.lo, part.hi),
                                  mine.source);
    else
        solver->setSource(device.marchQueue, mine.source);
}

// The iterations, with the ranks trading faces, and the flux gathered on rank 0.
void TransportSolver::Impl::sweep() {
    const DomSolver::Run run = solver->run(device.marchQueue, p.tolerance, p.maxIterations);
    r.iterations = run.iterations;
    r.converged = run.converged;
    r.device = device.name();
    r.ranks = ranks();
    r.cellFlux = gatherFlux(p, solver->totalFlux(device.marchQueue), p.bands * p.bands, part, peers);
    if (halo) {
        double sent = halo->bytesSent();
        halo->sum(&sent, 1);
        r.haloBytesPerIteration = run.iterations > 0 ? sent / run.iterations : 0.0;
    }
    if (rank() == 0) {
        const Vec3 edges = p.domain.extent() / Vec3(p.cells[0], p.cells[1], p.cells[2]);
        for (const Vec3& x : p.points) {
            int c[3];
            for (int a = 0; a < 3; ++a)
                c[a] = std::clamp(int(std::floor((x[a] - p.domain.min[a]) / edges[a])), 0, p.cells[a] - 1);
            r.flux.push_back(r.cellFlux[GridIndex{p.cells}(c[0], c[1], c[2])]);
        }
    }
    r.seconds = stopwatch.seconds();
}

TransportSolver::TransportSolver(const TransportProblem& problem, const Peers* peers)
    : impl_(std::make_unique<Impl>(problem, peers)) {
    try {
        impl_->prepare();
    } catch (const cl::Error& e) {
        throw Error("OpenCL device '" + impl_->device.name() + "': " + e.what() + " failed for " + impl_->what + ": " +
                    clErrorText(e.err()));
    }
}

TransportSolver::~TransportSolver() = default;

TransportResult TransportSolver::solve() {
    try {
        impl_->sweep();
        return impl_->r;
    } catch (const cl::Error& e) {
        throw Error("OpenCL device '" + impl_->device.name() + "': " + e.what() + " failed for " + impl_->what + ": " +
                    clErrorText(e.err()));
    }
}

TransportResult solveTransport(const TransportProblem& problem, const Peers* peers) {
    return TransportSolver(problem, peers).solve();
}

}  // namespace lucent::hybrid
