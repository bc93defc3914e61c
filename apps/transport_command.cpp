#include <cstdio>
#include <memory>
#include <optional>

#include "apps/commands.h"
#include "apps/mpi_ranks.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/input_file.h"
#include "core/transport_problem.h"
#include "core/vdb_output.h"
#ifdef LUCENT_HAVE_OPENCL
#include "hybrid/transport.h"
#endif

namespace lucent {

namespace {

void checkOutputs(const std::string& problem, const std::string& output, const std::string& volume) {
    checkOutputIsNoInput(output, {problem});
    checkWritable(output);
    if (volume.empty()) return;
    if (std::filesystem::path(volume).extension() != ".vdb")
        throw Error(volume, "--vdb writes OpenVDB files: the name must end in .vdb");
    checkOutputIsNoInput(volume, {problem});
    checkOutputsDistinct({output, volume});
    checkWritable(volume);
}

#ifdef LUCENT_HAVE_OPENCL
void writeResult(const TransportProblem& p, const hybrid::TransportResult& r, const std::string& output,
                 const std::string& volume) {
    AtomicFile out(output);
    std::ofstream& s = out.stream();
    s.precision(9);
    s << "x,y,z,flux\n";
    for (size_t i = 0; i < p.points.size(); ++i)
        s << p.points[i].x << ',' << p.points[i].y << ',' << p.points[i].z << ',' << r.flux[i] << '\n';
    // The volume first: if it cannot be written, neither file appears.
    if (!volume.empty())
        writeVdbGrid(volume, "flux", p.cells, p.domain.min,
                     p.domain.extent() / Vec3(p.cells[0], p.cells[1], p.cells[2]), r.cellFlux);
    out.commit();
    if (!r.uncollidedWhy.empty()) std::fprintf(stderr, "lucent: transport: %s\n", r.uncollidedWhy.c_str());
    std::string shared;
    if (r.ranks > 1)
        shared = ", " + std::to_string(r.ranks) + " ranks trading " +
                 std::to_string(r.haloBytesPerIteration / (1 << 20)).substr(0, 6) + " MiB per iteration";
    std::fprintf(stderr,
                 "lucent: transport: %d directions, %d moments, uncollided flux %s, %d iterations%s in %.2f s on "
                 "'%s'%s\n",
                 p.directions, p.bands * p.bands, r.uncollidedMarched ? "marched" : "swept", r.iterations,
                 r.converged ? "" : " (not converged)", r.seconds, r.device.c_str(), shared.c_str());
}
#endif

}  // namespace

Command addTransportCommand(CLI::App& app) {
    auto problem = std::make_shared<std::string>();
    auto output = std::make_shared<std::string>();
    CLI::App* sub = app.add_subcommand(
        "transport",
        "Solve a transport problem file with the discrete ordinates solver (docs/transport.md). Under mpirun, the "
        "ranks share the sweeps (a build with OpenMPI, libopenmpi-dev; docs/mpi.md)");
    sub->add_option("problem", *problem, "Problem file (.json)")->required();
    sub->add_option("-o,--output", *output, "Flux at the problem's points (.csv: x,y,z,flux)")->required();
    auto volume = std::make_shared<std::string>();
    sub->add_option("--vdb", *volume, "Also the flux in every cell, as an OpenVDB float grid named 'flux' (.vdb)");
    return [problem, output, volume] {
        Ranks ranks;
        // Every rank reads the problem, checks the outputs and prepares its
        // share; a failure there is agreed on, so that no rank is left waiting
        // in the sweeps.
        std::optional<TransportProblem> p;
        std::string failure;
#ifdef LUCENT_HAVE_OPENCL
        std::optional<hybrid::TransportSolver> solver;
#endif
        try {
            p = parseTransportProblem(*problem);
            checkOutputs(*problem, *output, *volume);
#ifdef LUCENT_HAVE_OPENCL
            solver.emplace(*p, &ranks);
#endif
        } catch (const Error& e) {
            failure = e.what();
        } catch (const std::bad_alloc&) {
            failure = "out of memory";
        }
        ranks.leaveIfAnyFailed(failure);
#ifdef LUCENT_HAVE_OPENCL
        hybrid::TransportResult r;
        try {
            r = solver->solve();
        } catch (const Error& e) {
            ranks.abortJob(e.what());  // the others may be waiting for this rank's faces
        } catch (const std::bad_alloc&) {
            ranks.abortJob("out of memory");
        }
        if (ranks.rank() == 0) writeResult(*p, r, *output, *volume);
#else
        throw Error(*problem +
                    ": lucent transport needs OpenCL, and this build has none (install the OpenCL "
                    "packages with scripts/install-deps.sh and rebuild)");
#endif
    };
}

}  // namespace lucent
