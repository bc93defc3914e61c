#include "bench/accuracy_sweep.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <map>

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/stopwatch.h"
#include "core/image_compare.h"
#include "core/loaded_scene.h"
#include "core/scene.h"
#include "methods/method_table.h"
#include "runtime/offscreen_frame.h"
#include "runtime/scattering_renderer.h"

namespace lucent {
namespace {

std::string format(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", v);
    return text;
}

struct Knob {
    const char* name;
    std::vector<double> values;
    void (*apply)(SweepSetting&, double);
};

const std::vector<Knob>& knobs() {
    static const std::vector<Knob> table = {
        {"samples",
         {5000, 10000, 20000, 40000, 80000},
         [](SweepSetting& s, double v) { s.preprocess.samples = int(v); }},
        {"published",
         {5000, 10000, 20000, 40000, 80000},
         [](SweepSetting& s, double v) {
             s.preprocess = publishedScheme(s.preprocess);
             s.preprocess.samples = int(v);
         }},
        {"heuristic-directions",
         {16, 32, 64, 128},
         [](SweepSetting& s, double v) { s.preprocess.heuristicDirections = int(v); }},
        {"projection-directions",
         {32, 64, 128, 256, 512},
         [](SweepSetting& s, double v) { s.preprocess.projectionDirections = int(v); }},
        {"sh-order", {2, 3, 4, 5, 6, 7, 8}, [](SweepSetting& s, double v) { s.preprocess.shOrder = int(v); }},
        {"width-factor", {1.0, 1.25, 1.5, 2.0, 2.5}, [](SweepSetting& s, double v) { s.preprocess.widthFactor = v; }},
        {"cutoff", {1e-1, 3e-2, 1e-2, 1e-3, 1e-4}, [](SweepSetting& s, double v) { s.cutoff = v; }},
        {"layer-spacing", {0.25, 0.5, 0.75, 1.0}, [](SweepSetting& s, double v) { s.preprocess.layerSpacing = v; }},
        {"traced-light", {0, 1}, [](SweepSetting& s, double v) { s.tracedLight = v != 0.0; }},
    };
    return table;
}

// Settings that preprocess alike share one sample set.
std::string preprocessKey(const PreprocessSettings& p) {
    char key[256];
    std::snprintf(key, sizeof key, "%d/%d/%d/%d/%g/%g/%d", p.samples, p.heuristicDirections, p.projectionDirections,
                  p.shOrder, p.widthFactor, p.layerSpacing, int(p.scheme));
    return key;
}

const char* kCsvHeader =
    "scene,knob,value,samples,preprocess_s,frame_ms,rel_rmse,mare,interior_rel_rmse,interior_mare,mean_ratio\n";

}  // namespace

std::vector<std::string> accuracyKnobNames() {
    std::vector<std::string> names;
    for (const auto& k : knobs()) names.push_back(k.name);
    return names;
}

std::vector<SweepSetting> accuracySweep(const std::vector<std::string>& wanted, const PreprocessSettings& base) {
    for (const auto& name : wanted)
        if (std::none_of(knobs().begin(), knobs().end(), [&](const Knob& k) { return name == k.name; })) {
            std::string names;
            for (const std::string& n : accuracyKnobNames()) names += (names.empty() ? "" : ", ") + n;
            throw Error("unknown knob '" + name + "' (expected one of: " + names + ")");
        }
    std::vector<SweepSetting> settings;
    for (const auto& knob : knobs()) {
        if (!wanted.empty() && std::find(wanted.begin(), wanted.end(), knob.name) == wanted.end()) continue;
        for (double v : knob.values) {
            SweepSetting s;
            s.knob = knob.name;
            s.value = format(v);
            s.preprocess = base;
            knob.apply(s, v);
            settings.push_back(s);
        }
    }
    return settings;
}

std::vector<SweepRow> runAccuracyBench(const std::vector<std::filesystem::path>& sceneFiles,
                                       const AccuracyBenchOptions& options, const std::filesystem::path& csvFile) {
    const std::vector<SweepSetting> settings = accuracySweep(options.knobs, options.base);
    checkWritable(csvFile);
    std::vector<SweepRow> rows;
    std::string csv = kCsvHeader;
    auto flushCsv = [&] {
        AtomicFile out(csvFile);
        out.stream() << csv;
        out.commit();
    };
    const auto context = OffscreenContext::create(options.backend);

    for (const auto& sceneFile : sceneFiles) {
        SceneDesc scene = parseScene(sceneFile);
        if (options.size > 0) scene.camera.width = scene.camera.height = options.size;
        LoadedScene loaded = loadScene(scene, false);
        const std::vector<VolumeObject>& objects = loaded.objects;
        const std::string sceneName = sceneFile.stem().string();
        const Bounds3 bounds = loaded.bounds();

        std::fprintf(stderr, "lucent: bench: %s: reference (%dx%d, tolerance %g)\n", sceneName.c_str(),
                     scene.camera.width, scene.camera.height, options.referenceTolerance);
        MethodSettings referenceSettings;
        referenceSettings.surface = false;
        const MethodEntry& exact = findMethod("reference");
        const Image reference =
            renderWith(exact, *exact.create(MethodOptions(exact.options).set("tolerance", options.referenceTolerance)),
                       loaded, referenceSettings);

        const ViewSetup view = viewSetupFor(scene.camera, bounds);
        OffscreenFrame frame(view.width, view.height);
        std::map<std::string, std::pair<std::vector<SampleSet>, double>> preprocessed;
        for (size_t k = 0; k < settings.size(); ++k) {
            const SweepSetting& setting = settings[k];
            std::fprintf(stderr, "lucent: bench: %s: %zu/%zu: %s = %s\n", sceneName.c_str(), k + 1, settings.size(),
                         setting.knob.c_str(), setting.value.c_str());
            auto& [sampleSets, preprocessSeconds] = preprocessed[preprocessKey(setting.preprocess)];
            if (sampleSets.empty()) {
                const Stopwatch stopwatch;
                for (const auto& o : objects) sampleSets.push_back(preprocessObject(o, setting.preprocess));
                preprocessSeconds = stopwatch.seconds();
            }
            // In memory, but through the sample-file contract: made for these objects.
            attachSamples(loaded, sampleSets);
            ScatteringRenderer renderer(setting.cutoff);
            size_t sampleCount = 0;
            for (size_t i = 0; i < objects.size(); ++i) {
                renderer.addObject(translucentObjectFor(objects[i], loaded.samples[i]));
                sampleCount += loaded.samples[i].size();
            }
            renderer.setLights(scene.lights);
            DrawOptions draw;
            draw.surface = false;
            draw.tracedLight = setting.tracedLight;
            const double frameSeconds = medianFrameSeconds(
                options.warmup, options.frames, [&] { frame.bindAndClear(); }, [&] { renderer.draw(view, draw); });
            const Image image = frame.read();
            const ImageError all = compareImages(image, reference), interior = compareImages(image, reference, 3);

            SweepRow row{sceneName,
                         setting.knob,
                         setting.value,
                         sampleCount,
                         preprocessSeconds,
                         1e3 * frameSeconds,
                         all.relativeRmse,
                         all.meanAbsoluteRelativeError,
                         interior.relativeRmse,
                         interior.meanAbsoluteRelativeError,
                         all.meanRatio};
            rows.push_back(row);
            char line[512];
            std::snprintf(line, sizeof line, "%s,%s,%s,%zu,%.4f,%.3f,%.5f,%.5f,%.5f,%.5f,%.5f\n", row.scene.c_str(),
                          row.knob.c_str(), row.value.c_str(), row.samples, row.preprocessSeconds,
                          row.frameMilliseconds, row.relativeRmse, row.mare, row.interiorRelativeRmse, row.interiorMare,
                          row.meanRatio);
            csv += line;
            flushCsv();
            std::fprintf(
                stderr,
                "lucent: bench:   %zu samples, preprocess %.2f s, frame %.1f ms, rel. RMSE %.2f%% (interior %.2f%%)\n",
                row.samples, row.preprocessSeconds, row.frameMilliseconds, 100 * row.relativeRmse,
                100 * row.interiorRelativeRmse);
        }
    }
    return rows;
}

ResultsRecord recordAccuracyBench(const std::vector<SweepRow>& rows, const AccuracyBenchOptions& options) {
    ResultsRecord out = ResultsRecord::ofThisProcess("lucent bench accuracy");
    const auto context =
        OffscreenContext::create(options.backend);  // the sweep's is gone; this names the same renderer
    out.addDevice(std::string(context->backendName()) + ": " + glRenderer());
    out.print(
        "each knob moved away from the preset while the others stay; --method ss, median of %d frames after %d "
        "warm-up, against --method reference (tolerance %g); errors are relative RMSE\n\n",
        options.frames, options.warmup, options.referenceTolerance);
    out.tableHeader({"scene", "knob", "value", "samples", "preprocessing (s)", "frame (ms)", "error, all pixels",
                     "error, 3 px inside", "mean ratio"},
                    {false, false, true, true, true, true, true, true, true});
    for (const SweepRow& r : rows)
        out.print("| %s | %s | %s | %zu | %.2f | %.1f | %.2f%% | %.2f%% | %.3f |\n", r.scene.c_str(), r.knob.c_str(),
                  r.value.c_str(), r.samples, r.preprocessSeconds, r.frameMilliseconds, 100.0 * r.relativeRmse,
                  100.0 * r.interiorRelativeRmse, r.meanRatio);
    return out;
}

}  // namespace lucent
