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
//                                  [--variant "--method ss"]... [--lights 1,8]
//                                  [--out DIR] [--record docs/results/command.md]
//
// Prints, per set of options, the wall time (min, median, max), the median
// processor time and peak resident set, and the baseline's median over its own.
// With --lights, each variant also runs on the scene with its first light as
// that many lights (sceneWithLights), in the same rounds: what a light costs
// one image, the whole command included.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
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

// The scene with its lights replaced by n copies of its first, each with 1/n of
// its intensity: the image stays the same, so only the lights' own cost
// changes (lucent-bench-render's lights table does the same for one frame).
// Written into dir, with the objects' mesh and samples made absolute; a scene
// that names other files (an environment, blockers, a density) is refused.
std::filesystem::path writeSceneWithLights(const std::filesystem::path& scene, int n, const std::filesystem::path& dir);
std::filesystem::path sceneWithLights(const std::filesystem::path& scene, int n, const std::filesystem::path& dir) {
    try {
        return writeSceneWithLights(scene, n, dir);
    } catch (const nlohmann::json::exception& e) {
        throw Error(scene.string(), std::string("--lights: ") + e.what());
    }
}

std::filesystem::path writeSceneWithLights(const std::filesystem::path& scene, int n,
                                           const std::filesystem::path& dir) {
    std::ifstream in(scene);
    nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
    if (j.is_discarded() || !j.is_object()) throw Error(scene.string(), "--lights needs a JSON scene file");
    if (!j.contains("lights") || !j["lights"].is_array() || j["lights"].empty())
        throw Error(scene.string(), "--lights needs a scene with a light");
    if (j.contains("environment")) throw Error(scene.string(), "--lights takes no scene with an environment");
    nlohmann::json light = j["lights"][0];
    nlohmann::json& intensity = light["intensity"];
    if (intensity.is_number()) {
        intensity = intensity.get<double>() / n;
    } else if (intensity.is_array()) {
        for (auto& c : intensity) c = c.get<double>() / n;
    } else {
        throw Error(scene.string(), "--lights needs the first light's intensity");
    }
    j["lights"] = nlohmann::json::array();
    for (int k = 0; k < n; ++k) j["lights"].push_back(light);
    const std::filesystem::path base = std::filesystem::absolute(scene).parent_path();
    if (!j.contains("objects") || !j["objects"].is_array()) throw Error(scene.string(), "--lights: no objects");
    for (auto& o : j["objects"]) {
        const nlohmann::json& medium = o.value("medium", nlohmann::json::object());
        if (medium.contains("blockers") || medium.contains("density"))
            throw Error(scene.string(), "--lights takes no scene with blockers or densities");
        for (const char* key : {"mesh", "samples"})
            if (o.contains(key) && o[key].is_string()) o[key] = (base / o[key].get<std::string>()).string();
    }
    const std::filesystem::path out = dir / ("lights-" + std::to_string(n) + ".json");
    AtomicFile file(out);
    file.stream() << j.dump(2) << "\n";
    file.commit();
    return out;
}

// The --lights rows: each variant's median at each count against its first count's.
void printLightRows(ResultsRecord& out, const std::vector<Variant>& runs, const std::vector<int>& lights) {
    out.print(
        "\nthe same with the scene's first light as n lights at one place, each 1/n of its intensity "
        "(the same image):\n\n");
    out.tableHeader({"options", "lights", "wall (s): median", "processor (s)", "this / first, at the medians",
                     "this / first, per round (median)"},
                    {false, true, true, true, true, true});
    for (size_t k = 0; k < runs.size(); ++k) {
        const Variant& first = runs[k - k % lights.size()];
        std::vector<double> perRound;
        for (size_t i = 0; i < runs[k].wall.size(); ++i) perRound.push_back(runs[k].wall[i] / first.wall[i]);
        out.print("| `%s` | %d | %.3f | %.3f | %.2fx | %.2fx |\n", runs[k].options.c_str(), lights[k % lights.size()],
                  median(runs[k].wall), median(runs[k].cpu), median(runs[k].wall) / median(first.wall),
                  median(perRound));
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
    std::vector<int> lightCounts;
    app.add_option("--lights", lightCounts,
                   "Also run each variant with the scene's first light as this many lights (comma-separated)")
        ->delimiter(',')
        ->check(CLI::Range(1, 256));
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
        // The --lights runs: every variant at each count, on its own scene.
        std::vector<Variant> lightRuns;
        std::vector<std::string> lightScenes;
        for (const int n : lightCounts) lightScenes.push_back(sceneWithLights(scene, n, dir).string());
        for (const std::string& options : variants)
            for (size_t c = 0; c < lightCounts.size(); ++c) lightRuns.push_back({options, words(options), {}, {}, {}});
        auto image = [&](size_t k) { return dir / ("image-" + std::to_string(k) + ".pfm"); };
        auto log = [&](size_t k) { return dir / ("run-" + std::to_string(k) + ".log"); };

        std::fprintf(stderr, "lucent-bench-command: warm-up round (shader and page caches)\n");
        const size_t L = lightCounts.size();
        auto lightScene = [&](size_t k) { return lightScenes[k % L]; };
        for (size_t k = 0; k < runs.size(); ++k) runOnce(lucent, scene, size, runs[k], image(k), log(k), false);
        for (size_t k = 0; k < lightRuns.size(); ++k)
            runOnce(lucent, lightScene(k), size, lightRuns[k], image(runs.size() + k), log(runs.size() + k), false);
        for (int round = 0; round < rounds; ++round) {
            for (size_t k = 0; k < runs.size(); ++k) {
                std::this_thread::sleep_for(std::chrono::duration<double>(idle));
                runOnce(lucent, scene, size, runs[k], image(k), log(k), true);
            }
            for (size_t k = 0; k < lightRuns.size(); ++k) {
                std::this_thread::sleep_for(std::chrono::duration<double>(idle));
                runOnce(lucent, lightScene(k), size, lightRuns[k], image(runs.size() + k), log(runs.size() + k), true);
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
        if (!lightRuns.empty()) printLightRows(out, lightRuns, lightCounts);
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
