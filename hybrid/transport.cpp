#include "hybrid/transport.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "core/stopwatch.h"
#include "hybrid/internal/dom_solver.h"
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

}  // namespace

TransportResult solveTransport(const TransportProblem& p) {
    const Stopwatch stopwatch;
    ClDevice device;
    DomGrid grid;
    grid.dims = p.cells;
    grid.edges = p.domain.extent() / Vec3(p.cells[0], p.cells[1], p.cells[2]);
    const size_t count = grid.count();
    const std::string what = "the " + std::to_string(p.cells[0]) + "x" + std::to_string(p.cells[1]) + "x" +
                             std::to_string(p.cells[2]) + " cells of " + p.file.string();
    // The host's copies: the source and the flux read back (M float4 per cell), the materials.
    device.checkMemory(DomSolver::bytesFor(p.cells, p.directions, p.bands), DomSolver::largestBufferFor(count, p.bands),
                       what, count * size_t(2 * p.bands * p.bands + 3) * sizeof(glm::vec4));
    grid.extinction.assign(count,
                           glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));  // a flux wanted everywhere: points may lie in vacuum
    grid.scattering.assign(count, glm::vec4(0.0f));
    grid.phase.assign(count, glm::vec4(0.0f));
    const int moments = p.bands * p.bands;
    std::vector<glm::vec4> source(count * moments, glm::vec4(0.0f));
    std::vector<double> density(count, 0.0);
    // Cells belong to the last region holding their centre; the rest are vacuum.
    for (int k = 0; k < p.cells[2]; ++k)
        for (int j = 0; j < p.cells[1]; ++j)
            for (int i = 0; i < p.cells[0]; ++i) {
                const Vec3 centre = p.domain.min + grid.edges * Vec3(i + 0.5, j + 0.5, k + 0.5);
                const TransportRegion* in = nullptr;
                for (const TransportRegion& r : p.regions)
                    if (r.box.contains(centre)) in = &r;
                if (!in) continue;
                const size_t v = i + size_t(p.cells[0]) * (j + size_t(p.cells[1]) * k);
                const DeltaM dm = deltaM(in->g, p.bands);
                grid.extinction[v] = glm::vec4(glm::vec3(float(in->sigmaT - dm.f * in->sigmaS)), 1.0f);
                grid.scattering[v] = glm::vec4(glm::vec3(float((1.0 - dm.f) * in->sigmaS)), 0.0f);
                grid.phase[v] = glm::vec4(float(in->g), 0.0f, 0.0f, 0.0f);
                // An isotropic emission q / (4 pi) per unit length: its zero moment is q / sqrt(4 pi).
                source[v * moments] = glm::vec4(glm::vec3(float(in->source / std::sqrt(4.0 * kPi))), 0.0f);
                density[v] = in->source;
            }
    TransportResult r;
    const size_t sourceCells = size_t(std::count_if(density.begin(), density.end(), [](double q) { return q > 0.0; }));
    std::string whyNot = sourceCells == 0 ? "" : whyNotMarched(p, grid, sourceCells);
    if (p.uncollided == TransportProblem::Uncollided::Marched && !whyNot.empty())
        throw Error(p.file.string() +
                    ": /solver/uncollided: cannot be \"marched\": " + whyNot.substr(0, whyNot.find(';')));
    if (p.uncollided == TransportProblem::Uncollided::Auto && whyNot.empty() && sourceCells > 0)
        whyNot = whyNotAuto(p, grid, density, sourceCells);
    r.uncollidedMarched = p.uncollided != TransportProblem::Uncollided::Swept && whyNot.empty() && sourceCells > 0;
    if (p.uncollided == TransportProblem::Uncollided::Auto) r.uncollidedWhy = whyNot;
    try {
        DomSolver solver(device, grid, p.directions, p.bands, p.reflective);
        if (r.uncollidedMarched) {
            // The first-collision source: generation zero integrated, the sweeps carry the rest.
            source = uncollidedFlux(grid, density, p.bands, p.reflective);
            solver.setUncollidedFlux(device.marchQueue, source);
        } else {
            solver.setSource(device.marchQueue, source);
        }
        const DomSolver::Run run = solver.run(device.marchQueue, p.tolerance, p.maxIterations);
        const std::vector<glm::vec4> flux = solver.totalFlux(device.marchQueue);
        r.iterations = run.iterations;
        r.converged = run.converged;
        r.device = device.name();
        r.cellFlux.resize(count);
        for (size_t v = 0; v < count; ++v) r.cellFlux[v] = float(double(flux[v * moments].r) * std::sqrt(4.0 * kPi));
        for (const Vec3& x : p.points) {
            int c[3];
            for (int a = 0; a < 3; ++a)
                c[a] = std::clamp(int(std::floor((x[a] - p.domain.min[a]) / grid.edges[a])), 0, p.cells[a] - 1);
            const size_t v = c[0] + size_t(p.cells[0]) * (c[1] + size_t(p.cells[1]) * c[2]);
            r.flux.push_back(double(flux[v * moments].r) * std::sqrt(4.0 * kPi));  // phi = sqrt(4 pi) phi_00
        }
        r.seconds = stopwatch.seconds();
        return r;
    } catch (const cl::Error& e) {
        throw Error("OpenCL device '" + device.name() + "': " + e.what() + " failed for " + what + ": " +
                    clErrorText(e.err()));
    }
}

}  // namespace lucent::hybrid
