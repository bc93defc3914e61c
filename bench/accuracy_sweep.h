#pragma once
// `lucent bench accuracy`: how much each quality knob buys (DESIGN.md, Accuracy).
// For every scene, one knob at a time moves away from the default quality while
// the others stay put; each setting is preprocessed, rendered with --method ss
// (median frame time after warm-up) and compared with --method reference.
#include <filesystem>
#include <string>
#include <vector>

#include "bench/results_record.h"
#include "core/method.h"
#include "preprocess/preprocessor.h"
#include "runtime/offscreen_context.h"

namespace lucent {

// One setting of the sweep: a knob, the value it takes, and everything that follows.
struct SweepSetting {
    std::string knob, value;
    PreprocessSettings preprocess;
    double cutoff = kDefaultGaussianCutoff;  // runtime: a Gaussian is drawn where it exceeds this fraction of its peak
    bool tracedLight = true;                 // runtime: DrawOptions::tracedLight
};

// The knobs: samples, published (the thesis scheme against samples),
// heuristic-directions, projection-directions, sh-order, width-factor, cutoff,
// layer-spacing, traced-light (0: the SH, 1: traced). Throws Error for an unknown name.
std::vector<std::string> accuracyKnobNames();
std::vector<SweepSetting> accuracySweep(const std::vector<std::string>& knobs, const PreprocessSettings& base);

struct SweepRow {
    std::string scene, knob, value;
    size_t samples = 0;
    double preprocessSeconds = 0.0, frameMilliseconds = 0.0;
    double relativeRmse = 0.0, mare = 0.0;                  // all pixels
    double interiorRelativeRmse = 0.0, interiorMare = 0.0;  // 3 px away from the silhouette
    double meanRatio = 0.0;
};

struct AccuracyBenchOptions {
    std::vector<std::string> knobs;  // empty: all
    int size = 0;                    // image width and height (0: the scene camera's)
    int frames = 7, warmup = 2;
    double referenceTolerance = 1e-3;
    GlBackend backend = GlBackend::Auto;
    PreprocessSettings base;  // the default quality
};

// Runs the sweep on every scene, appending rows to csvFile as they come (so that
// a long run shows progress and keeps what it measured).
std::vector<SweepRow> runAccuracyBench(const std::vector<std::filesystem::path>& scenes,
                                       const AccuracyBenchOptions& options, const std::filesystem::path& csvFile);

// The rows as a record of `lucent bench accuracy` (--record): one table, a row a setting.
ResultsRecord recordAccuracyBench(const std::vector<SweepRow>& rows, const AccuracyBenchOptions& options);

}  // namespace lucent
