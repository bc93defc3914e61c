// lucent.preprocess, lucent.render, lucent.methods and lucent.presets: the
// command line's preprocess and render (apps/) as functions, with the GIL
// released while they work and progress sent to a callback or to tqdm.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <tbb/global_control.h>

#include <chrono>
#include <cmath>
#include <memory>
#include <optional>

#include "core/error.h"
#include "core/input_file.h"
#include "core/loaded_scene.h"
#include "core/medium_presets.h"
#include "core/progress.h"
#include "core/sample_set.h"
#include "core/volume_object.h"
#include "methods/method_table.h"
#include "preprocess/preprocessor.h"
#include "python/bindings.h"
#include "python/vector_caster.h"

namespace lucent::python {
namespace {

namespace py = pybind11;

// Progress of the work this thread starts, to progress(stage, fraction) when
// given, else to a tqdm bar per stage when tqdm is installed, else nowhere
// (a notebook has no stderr line to redraw). Called from worker threads: each
// call takes the GIL.
class ProgressToPython {
public:
    explicit ProgressToPython(py::object callback) {
        if (callback.is_none()) {
            try {
                tqdm_ = py::module_::import("tqdm").attr("tqdm");
            } catch (const py::error_already_set&) {
                return;  // no tqdm: silent
            }
        } else {
            callback_ = std::move(callback);
        }
        previous_ = setThreadProgressSink(
            [this](const std::string& stage, double fraction, bool final) { report(stage, fraction, final); });
    }
    ~ProgressToPython() {
        if (callback_ || tqdm_) setThreadProgressSink(previous_);
        py::gil_scoped_acquire gil;
        if (bar_) bar_.attr("close")();
        bar_ = py::object();
        callback_ = py::object();
        tqdm_ = py::object();
    }
    ProgressToPython(const ProgressToPython&) = delete;
    ProgressToPython& operator=(const ProgressToPython&) = delete;

private:
    void report(const std::string& stage, double fraction, bool final) {
        py::gil_scoped_acquire gil;
        try {
            if (callback_) {
                callback_(stage, fraction);
                return;
            }
            if (!bar_ || stage != stage_) {
                if (bar_) bar_.attr("close")();
                bar_ = tqdm_(py::arg("total") = 100, py::arg("desc") = stage, py::arg("leave") = false);
                stage_ = stage;
                shown_ = 0;
            }
            const int now = int(std::lround(100.0 * fraction));
            if (now > shown_) bar_.attr("update")(now - shown_), shown_ = now;
            if (final) bar_.attr("close")(), bar_ = py::object();
        } catch (const py::error_already_set& e) {
            // A failing callback must not unwind through the renderer's threads.
            PyErr_WarnEx(PyExc_RuntimeWarning, (std::string("lucent progress callback failed: ") + e.what()).c_str(),
                         1);
        }
    }

    py::object callback_, tqdm_, bar_;
    std::string stage_;
    int shown_ = 0;
    ProgressSink previous_;
};

std::unique_ptr<tbb::global_control> threadLimit(int threads) {
    if (threads < 0 || threads > 1024) throw py::value_error("threads must lie in [0, 1024]");
    if (threads == 0) return nullptr;
    return std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, size_t(threads));
}

// The method's options as strings, as the command line types them.
std::map<std::string, std::string> optionValues(const py::dict& options) {
    std::map<std::string, std::string> values;
    for (const auto& [key, value] : options) {
        std::string name = py::str(key);
        for (char& c : name)
            if (c == '_') c = '-';
        if (py::isinstance<py::float_>(value)) {
            const double x = value.cast<double>();
            if (!std::isfinite(x)) throw py::value_error("option '" + name + "' must be finite");
        }
        values[name] = py::str(value);
    }
    return values;
}

py::array_t<float> toNumpy(const Image& image, size_t& nonFinite) {
    py::array_t<float> out({size_t(image.height), size_t(image.width), size_t(3)});
    auto view = out.mutable_unchecked<3>();
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            for (int c = 0; c < 3; ++c) {
                const float v = image.at(x, y)[c];
                const bool finite = std::isfinite(v);
                nonFinite += finite ? 0 : 1;
                view(y, x, c) = finite ? v : 0.0f;  // as the command writes them (docs/robustness.md)
            }
    return out;
}

struct RenderRun {
    Image image;
    std::string method, reason, servedBy;
    std::vector<std::string> warnings;
    double seconds = 0.0;
};

RenderRun renderScene(SceneDesc scene, const std::string& requested, const std::map<std::string, std::string>& given,
                      const MethodSettings& settings) {
    RenderRun run;
    const auto start = std::chrono::steady_clock::now();
    const ResolvedMethod method = resolveMethod(requested.empty() ? scene.render.method : requested, scene);
    std::vector<std::string> ignored;
    const MethodOptions options = methodOptions(*method.entry, given, !method.reason.empty(), ignored);
    const std::unique_ptr<Method> renderer = method.entry->create(options);
    renderer->prepare(scene, settings);
    LoadedScene loaded = loadScene(scene, method.entry->needsSamples);
    run.warnings = ignored;
    run.warnings.insert(run.warnings.end(), loaded.warnings.begin(), loaded.warnings.end());
    const std::vector<std::string> limits = renderer->limitations(loaded, settings);
    run.warnings.insert(run.warnings.end(), limits.begin(), limits.end());
    run.image = renderWith(*method.entry, *renderer, loaded, settings, &run.servedBy);
    run.method = method.entry->name;
    run.reason = method.reason;
    run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return run;
}

py::tuple render(const SceneDesc& sceneIn, const std::string& method, int width, int height, uint64_t seed, int threads,
                 bool surface, const py::dict& options, const py::object& progress) {
    SceneDesc scene = sceneIn;
    if (width < 0 || width > 16384 || height < 0 || height > 16384)
        throw py::value_error("width and height must lie in [1, 16384] (0: the scene camera's)");
    if (width) scene.camera.width = width;
    if (height) scene.camera.height = height;
    if (!method.empty() && method != "auto")
        findMethod(method);  // an unknown name: lucent.Error listing the built ones
    MethodSettings settings;
    settings.surface = surface && scene.render.surface;
    settings.threads = threads;
    settings.seed = seed;
    const std::map<std::string, std::string> given = optionValues(options);
    const auto limit = threadLimit(threads);
    RenderRun run;
    {
        ProgressToPython reporter(progress);
        py::gil_scoped_release released;
        run = renderScene(std::move(scene), method, given, settings);
    }
    size_t nonFinite = 0;
    py::array_t<float> image = toNumpy(run.image, nonFinite);
    if (nonFinite > 0)
        run.warnings.push_back(
            std::to_string(nonFinite) +
            " pixel(s) overflowed the single-precision range and are 0 (lower the light or sigma_t)");
    py::dict report;
    report["method"] = run.method;
    report["served_by"] = run.servedBy;
    report["reason"] = run.reason;  // why auto chose it; empty when the method was named
    report["warnings"] = run.warnings;
    report["seconds"] = run.seconds;
    return py::make_tuple(image, report);
}

py::list preprocess(const SceneDesc& scene, const std::string& quality, uint64_t seed, int threads, int samples,
                    const py::object& progress) {
    PreprocessSettings settings = qualityPreset(quality);
    if (samples < 0 || samples > 50000000) throw py::value_error("samples must lie in [0, 50000000]");
    if (samples) settings.samples = samples;
    settings.seed = seed;
    std::vector<std::filesystem::path> outputs;
    for (const auto& object : scene.objects) outputs.push_back(object.samples);
    checkOutputsDistinct(outputs);
    for (const auto& output : outputs) checkOutputIsNoInput(output, inputFilesOf(scene, false));
    const auto limit = threadLimit(threads);
    std::vector<SampleSet> sets;
    std::vector<double> seconds;
    std::vector<std::string> names;
    {
        ProgressToPython reporter(progress);
        py::gil_scoped_release released;
        std::vector<std::string> warnings;
        const std::vector<VolumeObject> objects = loadObjects(scene, warnings);
        // Every object first, then every file, as the command does: a failure
        // leaves no sample file of another object behind.
        for (const VolumeObject& object : objects) {
            PreprocessTimings timings;
            sets.push_back(preprocessObject(object, settings, &timings));
            seconds.push_back(timings.total());
            names.push_back(object.desc().name);
        }
        for (size_t i = 0; i < objects.size(); ++i) writeSampleFile(objects[i].desc().samples, sets[i]);
    }
    py::list out;
    for (size_t i = 0; i < sets.size(); ++i) {
        py::dict d;
        d["object"] = names[i];
        d["samples"] = sets[i].size();
        d["file"] = scene.objects[i].samples.string();
        d["seconds"] = seconds[i];
        out.append(d);
    }
    return out;
}

py::list methods() {
    py::list out;
    for (const MethodEntry& m : methodTable()) {
        py::dict d;
        d["name"] = m.name;
        d["summary"] = m.summary;
        d["needs_samples"] = m.needsSamples;
        d["interactive"] = m.interactive;
        d["unavailable"] = m.unavailableReason ? m.unavailableReason() : std::string();
        py::list options;
        for (const OptionSpec& o : m.options) {
            py::dict option;
            option["name"] = o.name;
            option["default"] = o.defaultValue;
            option["help"] = o.help;
            options.append(option);
        }
        d["options"] = options;
        out.append(d);
    }
    return out;
}

py::list presets() {
    py::list out;
    for (const MediumPreset& p : mediumPresets()) {
        py::dict d;
        d["name"] = p.name;
        d["source"] = p.source;
        d["sigma_t_per_mm"] = p.sigmaT();
        d["albedo"] = p.albedo();
        d["g"] = p.meanG();
        out.append(d);
    }
    return out;
}

}  // namespace

void bindRendering(py::module_& m) {
    m.def("render", &render, py::arg("scene"), py::arg("method") = "", py::arg("width") = 0, py::arg("height") = 0,
          py::arg("seed") = 1, py::arg("threads") = 0, py::arg("surface") = true, py::arg("options") = py::dict(),
          py::arg("progress") = py::none(),
          "Renders scene with method (default: the scene's, 'auto' picks one) and returns (image, report): image a "
          "float32 array of shape (height, width, 3) of linear radiance, row 0 at the top; report a dict with the "
          "method, what served it, why auto chose it, the warnings and the seconds taken. options: the method's own "
          "options by name (lucent.methods()), e.g. {'light': 'sh'}. progress: a callable (stage, fraction), or tqdm "
          "when installed. The GIL is released while it renders.");
    m.def("preprocess", &preprocess, py::arg("scene"), py::arg("quality") = "default", py::arg("seed") = 1,
          py::arg("threads") = 0, py::arg("samples") = 0, py::arg("progress") = py::none(),
          "Samples every object of scene and writes its sample file (object.samples), as lucent preprocess does; "
          "quality: draft, default or high. Returns one dict per object.");
    m.def("methods", &methods, "The methods this build has, with their options (docs/methods.md).");
    m.def("presets", &presets,
          "The measured media a scene file's medium can name with \"preset\" (coefficients per mm).");
}

}  // namespace lucent::python
