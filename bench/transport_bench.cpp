// `lucent transport` on Kobayashi's 3-D benchmark problems (models/transport/,
// docs/transport.md): every detector against its truth, with the solver's time
// and memory. Problem 1's truths are the published fluxes (bench/
// kobayashi_reference.h); the absorbers of problems 2 and 3 are checked against
// the uncollided flux integrated without cells (bench/uncollided_quadrature.h);
// their scattering cases against that plus the collided flux by our own Monte
// Carlo (bench/collided_monte_carlo.h), whose standard error is shown.
//
// --directions and --cell change the problem files' direction sets and cells,
// to see which of the two an error follows (docs/transport.md).
// --convergence runs one problem file against itself as its directions grow,
// where no independent truth exists (the scattering cube of docs/transport.md).
//
//   build/bin/lucent-bench-transport [--problems 1,2,3] [--cases absorber,scatter] [--details] [--repeats 3]
//                                    [--directions 24,48,...] [--cell CM] [--histories 4000000]
//                                    [--record docs/results/kobayashi.md]
//   build/bin/lucent-bench-transport --convergence models/transport/scattering-cube.json [--directions 24,48,120]
//                                    [--record docs/results/scattering-cube.md]
#include <CLI/CLI.hpp>

#include <sys/resource.h>

#include <cmath>
#include <cstdio>

#include "bench/collided_monte_carlo.h"
#include "bench/kobayashi_reference.h"
#include "bench/results_record.h"
#include "bench/uncollided_quadrature.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/statistics.h"
#include "core/transport_problem.h"
#include "hybrid/transport.h"

using namespace lucent;

namespace {

std::string format(const char* f, double v) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, f, v);
    return buffer;
}

// A point as the tables print it: (x, y, z).
std::string pointLabel(const Vec3& x) {
    char buffer[96];
    std::snprintf(buffer, sizeof buffer, "(%g, %g, %g)", x.x, x.y, x.z);
    return buffer;
}

double peakResidentMiB() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return usage.ru_maxrss / 1024.0;
}

// A truth is judged against where its relative standard error is at most this:
// a few percent, to judge the 10%.
constexpr double kJudged = 0.025;

// The truth at each point of problem `n`'s case (none where there is none),
// and its relative standard error where it is a Monte Carlo estimate of ours.
struct Truth {
    std::vector<double> value, error;
};

Truth truths(int n, const std::string& which, const TransportProblem& p, long histories) {
    Truth t;
    if (n == 1) {
        for (const KobayashiDetector& d : kKobayashiProblem1) {
            t.value.push_back(which == "absorber" ? d.absorber : d.scatter);
            t.error.push_back(which == "absorber" ? 0.0 : d.scatterError);  // exact, or the report's Monte Carlo
        }
        for (size_t i = 0; i < p.points.size(); ++i)
            if (p.points[i] != kKobayashiProblem1[i].at)
                throw Error(p.file.string() + ": its points are not problem 1's");
        return t;
    }
    for (const Vec3& x : p.points) t.value.push_back(uncollidedQuadrature(p, x, 256));
    t.error.assign(t.value.size(), 0.0);
    if (which == "scatter") {
        const CollidedEstimate c = collidedMonteCarlo(p, p.points, histories);
        for (size_t i = 0; i < t.value.size(); ++i) {
            t.value[i] += c.flux[i];
            t.error[i] = c.standardError[i] / t.value[i];
        }
    }
    return t;
}

// The problem files' settings, or the ones the command line asks for instead.
struct Overrides {
    std::vector<int> directions;  // each in turn; empty: the file's
    double cell = 0;              // cm along every axis; 0: the file's
};

TransportProblem withOverrides(TransportProblem p, int directions, double cell) {
    if (directions > 0) p.directions = directions;
    if (cell > 0)
        for (int a = 0; a < 3; ++a) p.cells[a] = std::max(1, int(std::lround(p.domain.extent()[a] / cell)));
    return p;
}

void kobayashi(ResultsRecord& out, const std::vector<int>& problems, const std::vector<std::string>& cases,
               bool details, int repeats, const Overrides& overrides, long histories) {
    out.print(
        "`lucent transport` on the problem files models/transport/kobayashi-N-CASE.json (2 cm cells, the\n"
        "benchmark's, and their direction sets, unless the command line says otherwise), against problem 1's\n"
        "published fluxes (exact for the absorber, Monte Carlo with scattering) and, for problems 2 and 3,\n"
        "the uncollided flux integrated without cells, plus with scattering the collided flux by our own\n"
        "Monte Carlo (bench/collided_monte_carlo.h; %ld histories per detector). Monte Carlo truths show\n"
        "their relative standard error. The errors are the solver's cell values against the point values\n"
        "at the detectors, judged where the truth is known to %.1f%% (a Monte Carlo truth with a larger\n"
        "standard error is shown, not judged). Time: the median of the repeated solves, uncollided flux\n"
        "included; memory: the process's peak resident set so far.\n\n",
        histories, 100.0 * kJudged);
    out.tableHeader({"problem", "case", "cells", "directions", "uncollided", "iterations", "time (s)",
                     "peak memory (MiB)", "detectors judged", "worst error", "mean absolute error", "worst at"},
                    {false, false, true, true, false, true, true, true, true, true, true, false});
    std::vector<std::string> lines;
    std::string device;
    const std::vector<int> directionSets = overrides.directions.empty() ? std::vector<int>{0} : overrides.directions;
    for (int n : problems)
        for (const std::string& which : cases) {
            Truth truth;
            for (int directions : directionSets) {
                const TransportProblem p = withOverrides(
                    parseTransportProblem(std::string(LUCENT_SOURCE_DIR) + "/models/transport/kobayashi-" +
                                          std::to_string(n) + "-" + which + ".json"),
                    directions, overrides.cell);
                const hybrid::TransportResult r = hybrid::solveTransport(p);
                std::vector<double> seconds{r.seconds};
                for (int k = 1; k < repeats; ++k) seconds.push_back(hybrid::solveTransport(p).seconds);
                if (device.empty()) out.addDevice("opencl: " + (device = r.device));
                if (truth.value.empty()) truth = truths(n, which, p, histories);
                double worst = 0.0, sum = 0.0;
                size_t at = 0, judged = 0;
                for (size_t i = 0; i < truth.value.size(); ++i) {
                    const double e = r.flux[i] / truth.value[i] - 1.0;
                    if (truth.error[i] <= kJudged) {
                        ++judged;
                        sum += std::abs(e);
                        if (std::abs(e) > std::abs(worst)) worst = e, at = i;
                    }
                    if (details) {
                        const Vec3& x = p.points[i];
                        char row[160];
                        std::snprintf(row, sizeof row, "| %d | %s | %d | (%g, %g, %g) | %.5g | %.5g | %s | %+.2f%% |\n",
                                      n, which.c_str(), p.directions, x.x, x.y, x.z, r.flux[i], truth.value[i],
                                      truth.error[i] > 0.0 ? format("%.1f%%", 100.0 * truth.error[i]).c_str() : "",
                                      100.0 * e);
                        lines.push_back(row);
                    }
                }
                const std::string where = pointLabel(p.points[at]);
                out.tableRow(
                    {std::to_string(n), which,
                     std::to_string(p.cells[0]) + "x" + std::to_string(p.cells[1]) + "x" + std::to_string(p.cells[2]),
                     std::to_string(p.directions), r.uncollidedMarched ? "marched" : "swept",
                     std::to_string(r.iterations), format("%.1f", median(seconds)), format("%.0f", peakResidentMiB()),
                     std::to_string(judged) + " of " + std::to_string(p.points.size()),
                     format("%+.1f%%", 100.0 * worst),
                     format("%.1f%%", 100.0 * sum / double(std::max<size_t>(judged, 1))), where});
            }
        }
    if (details && !lines.empty()) {
        out.print("\nEvery detector:\n\n");
        out.tableHeader(
            {"problem", "case", "directions", "detector (cm)", "flux", "truth", "truth's standard error", "error"},
            {false, false, true, false, true, true, true, true});
        for (const std::string& line : lines) out.print("%s", line.c_str());
    }
}

// A problem file's flux at its points as the directions grow, swept and
// marched, against the file's own solve as the converged value: where no
// independent truth exists, how far each direction set is from convergence
// (docs/transport.md, the scattering cube).
void convergence(ResultsRecord& out, const std::string& file, const std::vector<int>& directions) {
    const TransportProblem converged = parseTransportProblem(file);
    const hybrid::TransportResult truth = hybrid::solveTransport(converged);
    out.addDevice("opencl: " + truth.device);
    const std::string mode = truth.uncollidedMarched ? "marched" : "swept";
    out.print(
        "`lucent transport` on %s.\n\n"
        "The flux at its points with fewer directions, the uncollided flux swept and marched, against\n"
        "its own solve at %d directions (%s) as the converged value: a convergence study, not an\n"
        "independent truth. Time: each solve's, uncollided flux included.\n\n",
        file.c_str(), converged.directions, mode.c_str());
    std::vector<std::string> header{"point", "N = " + std::to_string(converged.directions) + " " + mode};
    std::vector<std::vector<std::string>> rows(converged.points.size());
    for (size_t i = 0; i < rows.size(); ++i) rows[i] = {pointLabel(converged.points[i]), format("%.4g", truth.flux[i])};
    std::vector<std::string> times{"time (s)", format("%.1f", truth.seconds)};
    for (int n : directions)
        for (const auto how : {TransportProblem::Uncollided::Swept, TransportProblem::Uncollided::Marched}) {
            TransportProblem p = converged;
            p.directions = n;
            p.uncollided = how;
            const hybrid::TransportResult r = hybrid::solveTransport(p);
            header.push_back("N = " + std::to_string(n) + (r.uncollidedMarched ? " marched" : " swept"));
            for (size_t i = 0; i < rows.size(); ++i)
                rows[i].push_back(format("%+.1f%%", 100.0 * (r.flux[i] / truth.flux[i] - 1.0)));
            times.push_back(format("%.1f", r.seconds));
        }
    std::vector<bool> numeric(header.size(), true);
    numeric[0] = false;
    out.tableHeader(header, numeric);
    for (const std::vector<std::string>& row : rows) out.tableRow(row);
    out.tableRow(times);
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"Lucent transport benchmark: Kobayashi's 3-D problems against their truths"};
    std::vector<int> problems{1, 2, 3};
    std::vector<std::string> cases{"absorber", "scatter"};
    bool details = false;
    std::string recordFile;
    app.add_option("--problems", problems, "Kobayashi's problems run")->delimiter(',')->check(CLI::Range(1, 3));
    app.add_option("--cases", cases, "Their cases")->delimiter(',')->check(CLI::IsMember({"absorber", "scatter"}));
    app.add_flag("--details", details, "Also every detector's flux, truth and error");
    int repeats = 3;
    app.add_option("--repeats", repeats, "Solves timed per problem (their median)")->check(CLI::Range(1, 100));
    Overrides overrides;
    app.add_option("--directions", overrides.directions, "Direction sets run in turn instead of the files'")
        ->delimiter(',')
        ->check(CLI::IsMember({24, 48, 80, 120, 168}));
    app.add_option("--cell", overrides.cell, "Cells of about this many cm instead of the files' 2 cm")
        ->check(CLI::Range(1.0, 50.0));
    long histories = 4000000;
    app.add_option("--histories", histories,
                   "Monte Carlo histories per detector of the truths of problems 2 and 3 with scattering")
        ->check(CLI::Range(1000L, 1000000000L));
    std::string convergenceFile;
    app.add_option("--convergence", convergenceFile,
                   "Instead of Kobayashi's problems: this problem file against itself as --directions grow "
                   "(default 24,48,120), swept and marched")
        ->check(CLI::ExistingFile);
    app.add_option("--record", recordFile, "Also write the results to this Markdown file (docs/results/)");
    CLI11_PARSE(app, argc, argv);
    try {
        if (!recordFile.empty()) checkWritable(recordFile);
        ResultsRecord out(argc, argv);
        if (!convergenceFile.empty())
            convergence(out, convergenceFile,
                        overrides.directions.empty() ? std::vector<int>{24, 48, 120} : overrides.directions);
        else
            kobayashi(out, problems, cases, details, repeats, overrides, histories);
        if (!recordFile.empty()) out.write(recordFile);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "lucent-bench-transport: error: %s\n", e.what());
        return 1;
    }
    return 0;
}
