// lucent transport with its sweeps shared among MPI ranks (docs/mpi.md,
// docs/scaling.md): on this machine, the solve time on 1, 2 and 4 ranks, the
// parallel efficiency and the bytes the ranks trade per iteration (measured,
// and by the formula); then what a rank holds and sends for cluster-sized
// grids, with the time an iteration would take at this machine's sweep rate.
// The problem is sweep-bound: a box of scattering medium (albedo 0.5) with a
// source in one corner, vacuum faces, the uncollided flux swept.
//
//   build/bin/lucent-bench-scaling [--cells 48] [--directions 48] [--ranks 1,2,4] [--repeats 3]
//                                  [--record docs/results/scaling.md]
#include <CLI/CLI.hpp>

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <regex>
#include <sstream>
#include <thread>

#include "bench/results_record.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/run_program.h"
#include "core/statistics.h"
#include "hybrid/transport.h"

using namespace lucent;
namespace fs = std::filesystem;

namespace {

std::string format(const char* f, double v) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, f, v);
    return buffer;
}

std::string gridName(const std::array<int, 2>& g) { return std::to_string(g[0]) + "x" + std::to_string(g[1]); }

void writeProblem(const fs::path& file, int cells, int directions) {
    std::ofstream out(file);
    out << "{\"domain\": {\"min\": [0, 0, 0], \"max\": [" << cells << ", " << cells << ", " << cells
        << "], \"cells\": [" << cells << ", " << cells << ", " << cells << "]},\n"
        << " \"regions\": [{\"min\": [0, 0, 0], \"max\": [" << cells << ", " << cells << ", " << cells
        << "], \"sigma_t\": 0.2, \"sigma_s\": 0.1},\n"
        << "  {\"min\": [0, 0, 0], \"max\": [4, 4, 4], \"sigma_t\": 0.2, \"sigma_s\": 0.1, \"source\": 1}],\n"
        << " \"points\": [[2, 2, 2], [" << cells - 2 << ", " << cells - 2 << ", " << cells - 2 << "]],\n"
        << " \"solver\": {\"directions\": " << directions << ", \"bands\": 1, \"uncollided\": \"swept\"}}\n";
    if (!out) throw Error(file.string(), "cannot write the benchmark's problem");
}

struct Solve {
    double seconds = 0, mibPerIteration = 0;
    int iterations = 0;
};

// One `mpirun -np ranks lucent transport`, its figures from the line it
// prints. bound: each rank bound to a core of its own (its device's threads
// with it); otherwise the ranks share every core.
Solve solve(const fs::path& lucent, const fs::path& dir, int ranks, bool bound) {
    const fs::path log = dir / "log";
    const std::vector<std::string> argv{"mpirun",
                                        "--quiet",
                                        "--oversubscribe",
                                        "--bind-to",
                                        bound ? "core" : "none",
                                        "-np",
                                        std::to_string(ranks),
                                        lucent.string(),
                                        "transport",
                                        (dir / "problem.json").string(),
                                        "-o",
                                        (dir / "flux.csv").string()};
    if (runProgram(argv, log) != 0)
        throw Error("mpirun with " + std::to_string(ranks) + " ranks failed (" + log.string() + ")");
    std::ifstream in(log);
    std::stringstream text;
    text << in.rdbuf();
    const std::string s = text.str();
    std::smatch m;
    Solve r;
    if (!std::regex_search(s, m, std::regex("(\\d+) iterations in ([0-9.]+) s")))
        throw Error(log.string(), "no solve line");
    r.iterations = std::stoi(m[1]);
    r.seconds = std::stod(m[2]);
    if (std::regex_search(s, m, std::regex("trading ([0-9.]+) MiB per iteration"))) r.mibPerIteration = std::stod(m[1]);
    return r;
}

// Cell-direction updates per second per core, from one rank on one core.
double measure(ResultsRecord& out, const fs::path& lucent, const fs::path& dir, int cells, int directions,
               const std::vector<int>& rankCounts, int repeats) {
    const int cores = int(std::max(1u, std::thread::hardware_concurrency()));
    out.print(
        "`lucent transport` under `mpirun --oversubscribe -np N` on a %d^3 box, %d directions, one band, the\n"
        "uncollided flux swept (sweep-bound). Ranks up to the %d cores are bound to a core each (`--bind-to\n"
        "core`, the OpenCL device's threads with them); one rank is also run on every core, and more ranks than\n"
        "cores share them. Time: the median of %d solves as rank 0 reports it; speed-up against one rank on\n"
        "one core; efficiency: the speed-up over the cores used. Sent: all ranks' bytes per iteration, as the\n"
        "solver counts them and by the formula 16 N nz (ny (px - 1) + nx (py - 1)).\n\n",
        cells, directions, cores, repeats);
    out.tableHeader({"ranks", "cores", "process grid", "iterations", "time (s)", "speed-up", "efficiency",
                     "sent per iteration (MiB)", "formula (MiB)"},
                    {true, true, false, true, true, true, true, true, true});
    struct Run {
        int ranks;
        bool bound;
    };
    std::vector<Run> runs{{1, true}};
    if (cores > 1) runs.push_back({1, false});
    for (int n : rankCounts)
        if (n > 1) runs.push_back({n, n <= cores});
    solve(lucent, dir, 1, false);  // untimed: the first run compiles the kernels into the cache
    double single = 0, rate = 0;
    for (const Run& run : runs) {
        std::vector<double> seconds;
        Solve s;
        for (int k = 0; k < repeats; ++k) seconds.push_back((s = solve(lucent, dir, run.ranks, run.bound)).seconds);
        const double t = median(seconds);
        if (single == 0) {
            single = t;
            rate = double(cells) * cells * cells * directions * s.iterations / t;
        }
        const int used = run.bound ? run.ranks : cores;
        const hybrid::TransportFootprint f =
            hybrid::transportFootprint({cells, cells, cells}, directions, 1, run.ranks, false);
        out.tableRow({std::to_string(run.ranks), std::to_string(used), gridName(f.processGrid),
                      std::to_string(s.iterations), format("%.2f", t), format("%.2f", single / t),
                      format("%.2f", single / t / used), format("%.3f", s.mibPerIteration),
                      format("%.3f", f.haloBytesPerIteration / (1 << 20))});
    }
    return rate;
}

// What a rank would hold and send at cluster sizes, and an iteration's time at
// `rate` per core with `coresPerRank`, KBA's pipeline idling included.
void project(ResultsRecord& out, double rate, int directions, int coresPerRank, double linkGBs) {
    out.print(
        "\nProjected for a cluster: each rank one node of %d cores sweeping at this machine's measured rate\n"
        "(%.3g cell-direction updates per second per core), %d directions, one band, the uncollided flux\n"
        "swept; memory from the solver's own accounting (DomSolver::bytesFor, the host's copies). An\n"
        "iteration: the largest share's updates times 1 + (px + py - 2) / blocks for the pipeline's fill,\n"
        "plus one rank's sent bytes over a %.0f GB/s link.\n\n",
        coresPerRank, rate, directions, linkGBs);
    out.tableHeader({"cells", "ranks", "process grid", "device per rank (GiB)", "host per rank (GiB)",
                     "sent per iteration (GiB)", "iteration (s)", "iterations per second"},
                    {false, true, false, true, true, true, true, true});
    for (int n : {128, 256, 512, 1024})
        for (int ranks : {1, 16, 64, 256, 1024}) {
            if (n <= 256 && ranks > 64) continue;
            const hybrid::TransportFootprint f = hybrid::transportFootprint({n, n, n}, directions, 1, ranks, false);
            const auto& g = f.processGrid;
            const double share = double(n / g[0]) * (n / g[1]) * n;  // cells of the largest share, about
            const double sweep =
                share * directions / (rate * coresPerRank) * (1.0 + double(f.pipelineStages) / f.blocks);
            const double link = f.haloBytesPerIteration / ranks / (linkGBs * 1e9);
            const double t = sweep + link;
            out.tableRow({std::to_string(n) + "^3", std::to_string(ranks), gridName(g),
                          format("%.2f", f.deviceBytes / double(1 << 30)),
                          format("%.2f", f.hostBytes / double(1 << 30)),
                          format("%.2f", f.haloBytesPerIteration / double(1 << 30)), format("%.3g", t),
                          format("%.3g", 1.0 / t)});
        }
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"Lucent scaling benchmark: lucent transport's sweeps shared among MPI ranks"};
    int cells = 48, directions = 48, repeats = 3, coresPerRank = 64;
    std::vector<int> ranks{1, 2, 4};
    std::string recordFile;
    app.add_option("--cells", cells, "Cells along each axis")->check(CLI::Range(8, 256));
    app.add_option("--directions", directions, "Discrete directions")->check(CLI::IsMember({8, 24, 48, 80, 120, 168}));
    app.add_option("--ranks", ranks, "Ranks run, the first the baseline")->delimiter(',')->check(CLI::Range(1, 64));
    app.add_option("--repeats", repeats, "Solves timed per rank count (their median)")->check(CLI::Range(1, 100));
    app.add_option("--cores-per-rank", coresPerRank, "Cores of a cluster node, for the projection")
        ->check(CLI::Range(1, 1024));
    app.add_option("--record", recordFile, "Also write the results to this Markdown file (docs/results/)");
    CLI11_PARSE(app, argc, argv);
    try {
        if (!recordFile.empty()) checkWritable(recordFile);
        if (geteuid() == 0) {  // OpenMPI refuses root without both
            setenv("OMPI_ALLOW_RUN_AS_ROOT", "1", 0);
            setenv("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1", 0);
        }
        char pattern[] = "/tmp/lucent-scaling-XXXXXX";
        if (!mkdtemp(pattern)) throw Error("cannot make a scratch directory in /tmp");
        const fs::path dir = pattern;
        writeProblem(dir / "problem.json", cells, directions);
        ResultsRecord out(argc, argv);
        const double rate = measure(out, siblingProgram("lucent"), dir, cells, directions, ranks, repeats);
        project(out, rate, directions, coresPerRank, 10.0);
        fs::remove_all(dir);
        if (!recordFile.empty()) out.write(recordFile);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "lucent-bench-scaling: error: %s\n", e.what());
        return 1;
    }
    return 0;
}
