#include <cstdio>
#include <memory>

#include "apps/commands.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/input_file.h"
#include "core/transport_problem.h"
#include "core/vdb_output.h"
#ifdef LUCENT_HAVE_OPENCL
#include "hybrid/transport.h"
#endif

namespace lucent {

Command addTransportCommand(CLI::App& app) {
    auto problem = std::make_shared<std::string>();
    auto output = std::make_shared<std::string>();
    CLI::App* sub = app.add_subcommand(
        "transport", "Solve a transport problem file with the discrete ordinates solver (docs/transport.md)");
    sub->add_option("problem", *problem, "Problem file (.json)")->required();
    sub->add_option("-o,--output", *output, "Flux at the problem's points (.csv: x,y,z,flux)")->required();
    auto volume = std::make_shared<std::string>();
    sub->add_option("--vdb", *volume, "Also the flux in every cell, as an OpenVDB float grid named 'flux' (.vdb)");
    return [problem, output, volume] {
        const TransportProblem p = parseTransportProblem(*problem);
        checkOutputIsNoInput(*output, {*problem});
        checkWritable(*output);
        if (!volume->empty()) {
            if (std::filesystem::path(*volume).extension() != ".vdb")
                throw Error(*volume, "--vdb writes OpenVDB files: the name must end in .vdb");
            checkOutputIsNoInput(*volume, {*problem});
            checkOutputsDistinct({*output, *volume});
            checkWritable(*volume);
        }
#ifdef LUCENT_HAVE_OPENCL
        const hybrid::TransportResult r = hybrid::solveTransport(p);
        AtomicFile out(*output);
        std::ofstream& s = out.stream();
        s.precision(9);
        s << "x,y,z,flux\n";
        for (size_t i = 0; i < p.points.size(); ++i)
            s << p.points[i].x << ',' << p.points[i].y << ',' << p.points[i].z << ',' << r.flux[i] << '\n';
        // The volume first: if it cannot be written, neither file appears.
        if (!volume->empty())
            writeVdbGrid(*volume, "flux", p.cells, p.domain.min,
                         p.domain.extent() / Vec3(p.cells[0], p.cells[1], p.cells[2]), r.cellFlux);
        out.commit();
        if (!r.uncollidedWhy.empty()) std::fprintf(stderr, "lucent: transport: %s\n", r.uncollidedWhy.c_str());
        std::fprintf(stderr,
                     "lucent: transport: %d directions, %d moments, uncollided flux %s, %d iterations%s in %.2f s on "
                     "'%s'\n",
                     p.directions, p.bands * p.bands, r.uncollidedMarched ? "marched" : "swept", r.iterations,
                     r.converged ? "" : " (not converged)", r.seconds, r.device.c_str());
#else
        throw Error(*problem +
                    ": lucent transport needs OpenCL, and this build has none (install the OpenCL "
                    "packages with scripts/install-deps.sh and rebuild)");
#endif
    };
}

}  // namespace lucent
