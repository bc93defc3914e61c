// The whole-command benchmark: `lucent render SCENE --width S --height S -o FILE`
// timed as a user runs it, a new process each time, so that starting the
// process, the OpenGL context, loading the scene and the sample file, a first
// frame's costs and writing the image all count (issue 13's "whole command").
// Each round runs every set of options in turn, after the same idle pause: on
// the virtual machines Lucent is measured on, memory a process frees is handed
// back to the host within seconds, and a run right after another finds it
// cheaper than a user's command after a pause does. A first, untimed round
// fills Mesa's shader cache and the page cache, so every timed run is a user's
// second run.
//
//   build/bin/lucent-bench-command [SCENE] [--size 800] [--rounds 8] [--idle 5]
//                                  [--baseline "--method reference"]
//                                  [--variant "--method ss"]... [--out DIR]
//                                  [--record docs/results/command.md]
//
// Prints, per set of options, the wall time (min, median, max), the median
// processor time and peak resident set, and the baseline's median over its own.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <thread>

#include "bench/results_record.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/run_program.h"
#include "core/statistics.h"
#include "core/stopwatch.h"

using namespace lucent;

namespace {

struct Variant {
    std::string options;  // as given, for the table
    std::vector<std::string> words;
    std::vector<double> wall, cpu, peakMb;
};

// Options are split at white space; no shell ever sees them.
std::vector<std::string> words(const std::string& options) {
    std::istringstream in(options);
    std::vector<std::string> out;
    for (std::string w; in >> w;) out.push_back(w);
    if (out.empty()) throw Error("an empty set of options (--variant or --baseline)");
    return out;
}

void runOnce(const std::filesystem::path& lucent, const std::string& scene, int size, Variant& v,
             const std::filesystem::path& image, const std::filesystem::path& log, bool timed) {
    std::vector<std::string> argv = {lucent.string(), "render", scene};
    argv.insert(argv.end(), v.words.begin(), v.words.end());
    for (const std::string& a : {std::string("--width"), std::to_string(size), std::string("--height"),
                                 std::to_string(size), std::string("-o"), image.string()})
        argv.push_back(a);
    ProgramUsage usage;
    const Stopwatch stopwatch;
    const int code = runProgram(argv, log, &usage);
    const double seconds = stopwatch.seconds();
    if (code != 0)
        throw Error(log.string(), "lucent render " + scene + " " + v.options + " failed (exit " + std::to_string(code) +
                                      "); its output is in this file");
    if (timed) {
        v.wall.push_back(seconds);
        v.cpu.push_back(usage.cpuSeconds);
        v.peakMb.push_back(double(usage.peakResidentKb) / 1024.0);
    }
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"Lucent whole-command benchmark: lucent render, a new process per run"};
    std::string scene = std::string(LUCENT_SOURCE_DIR) + "/models/bunny.json";
    int size = 800, rounds = 8;
    double idle = 5.0;
    std::string baseline = "--method reference", outDir = "command-bench";
    std::vector<std::string> variants = {"--method ss", "--method ss --light sh"};
    app.add_option("scene", scene, "Scene file (preprocessed: lucent preprocess SCENE)");
    app.add_option("--size", size, "Image width and height")->check(CLI::Range(16, 16384));
    app.add_option("--rounds", rounds, "Timed rounds (each runs every set of options once)")
        ->check(CLI::Range(1, 1000));
    app.add_option("--idle", idle, "Seconds of idle before each run")->check(CLI::Range(0.0, 600.0));
    app.add_option("--baseline", baseline, "The options the others are compared with");
    app.add_option("--variant", variants, "Options of a compared run (repeat the flag for more)");
    app.add_option("--out", outDir, "Directory for the images and the runs' output");
    std::string recordFile;
    app.add_option("--record", recordFile, "Also write the results to this Markdown file (docs/results/)");
    CLI11_PARSE(app, argc, argv);
    try {
        if (!recordFile.empty()) checkWritable(recordFile);
        ResultsRecord out(argc, argv);
        if (!std::isfinite(idle)) throw Error("--idle", "not a finite number of seconds");
        const std::filesystem::path lucent = siblingProgram("lucent");
        std::filesystem::create_directories(outDir);
        std::vector<Variant> runs;
        for (const std::string& options : variants) runs.push_back({options, words(options), {}, {}, {}});
        runs.push_back({baseline, words(baseline), {}, {}, {}});
        const std::filesystem::path dir(outDir);
        auto image = [&](size_t k) { return dir / ("image-" + std::to_string(k) + ".pfm"); };
        auto log = [&](size_t k) { return dir / ("run-" + std::to_string(k) + ".log"); };

        std::fprintf(stderr, "lucent-bench-command: warm-up round (shader and page caches)\n");
        for (size_t k = 0; k < runs.size(); ++k) runOnce(lucent, scene, size, runs[k], image(k), log(k), false);
        for (int round = 0; round < rounds; ++round) {
            for (size_t k = 0; k < runs.size(); ++k) {
                std::this_thread::sleep_for(std::chrono::duration<double>(idle));
                runOnce(lucent, scene, size, runs[k], image(k), log(k), true);
            }
            std::fprintf(stderr, "lucent-bench-command: round %d of %d done\n", round + 1, rounds);
        }

        const Variant& base = runs.back();
        const double baseMedian = median(base.wall);
        out.print("lucent render %s at %dx%d, %d rounds, %.1f s idle before each run\n\n",
                  std::filesystem::path(scene).filename().c_str(), size, size, rounds, idle);
        out.tableHeader({"options", "wall (s): min", "median", "max", "processor (s)", "peak resident (MB)",
                         "baseline / this, at the medians", "baseline / this, per round (median)"},
                        {false, true, true, true, true, true, true, true});
        for (const Variant& v : runs) {
            std::vector<double> perRound;
            for (size_t i = 0; i < v.wall.size(); ++i) perRound.push_back(base.wall[i] / v.wall[i]);
            const auto [lo, hi] = std::minmax_element(v.wall.begin(), v.wall.end());
            out.print("| `%s` | %.3f | %.3f | %.3f | %.3f | %.0f | %.2fx | %.2fx |\n", v.options.c_str(), *lo,
                      median(v.wall), *hi, median(v.cpu), median(v.peakMb), baseMedian / median(v.wall),
                      median(perRound));
        }
        if (!recordFile.empty()) out.write(recordFile);
    } catch (const Error& e) {
        std::fprintf(stderr, "lucent-bench-command: error: %s\n", e.what());
        return 1;
    } catch (const std::filesystem::filesystem_error& e) {
        std::fprintf(stderr, "lucent-bench-command: error: %s\n", e.what());
        return 1;
    }
    return 0;
}
