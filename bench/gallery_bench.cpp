// The gallery (docs/gallery.md): every method built here on the bundled scenes,
// beside the path tracer's full transport, each image with its error against
// that truth and its time.
//
//   build/bin/lucent-bench-gallery [SCENE.json...] [--size N] [--spp N] [--images DIR] [--record docs/gallery.md]
//
// Each scene's objects are preprocessed in memory at default quality. The
// truth is `--method path` rendered twice with independent seeds, so that its
// own noise is taken out of every error (core/image_compare.h). Every image of
// a scene is written at the truth's exposure, so that brightness compares.
#include <CLI/CLI.hpp>

#include <cstdio>

#include "bench/path_truth.h"
#include "bench/results_record.h"
#include "core/error.h"
#include "core/image_compare.h"
#include "core/loaded_scene.h"
#include "core/stopwatch.h"
#include "methods/method_table.h"
#include "preprocess/preprocessor.h"

using namespace lucent;
namespace fs = std::filesystem;

namespace {

// One scene: its table, one row per method, the truth first.
void gallery(ResultsRecord& out, const fs::path& sceneFile, int size, int spp, const fs::path& images,
             const fs::path& linkBase) {
    SceneDesc scene = parseScene(sceneFile);
    scene.camera.width = scene.camera.height = size;
    LoadedScene loaded = loadScene(scene, false);
    Stopwatch stopwatch;
    std::vector<SampleSet> samples;
    for (const VolumeObject& o : loaded.objects) samples.push_back(preprocessObject(o, qualityPreset("default")));
    attachSamples(loaded, std::move(samples));
    const double preprocessSeconds = stopwatch.seconds();
    MethodSettings settings;
    settings.surface = scene.render.surface;

    const std::string name = sceneFile.stem().string();
    std::fprintf(stderr, "lucent: gallery: %s: the truth, %d paths per pixel twice\n", name.c_str(), spp);
    const PathTruth truth = pathTruth(loaded, settings, spp);
    const float exposure = autoExposure(truth.mean);
    const auto picture = [&](const std::string& method, const Image& image) {
        const fs::path file = images / (name + "-" + method + ".png");
        writeImage(file, image, exposure);
        return "![" + name + ", " + method + "](" + (linkBase / file.filename()).generic_string() + ")";
    };
    out.print(
        "\n## %s\n\n%dx%d; %zu object(s), preprocessed in memory at default quality in %.1f s (what ss, lbl "
        "and mdom draw from); the truth's own noise is %.1f%%, taken out of the errors\n\n",
        name.c_str(), size, size, loaded.objects.size(), preprocessSeconds,
        100.0 * luminanceRelativeRmse(truth.a, truth.a, truth.b).noise);
    out.tableHeader({"image", "method", "relative RMSE against path", "mean against path", "time (s)"},
                    {false, false, true, true, true});
    out.tableRow({picture("path", truth.mean), "path (the truth, " + std::to_string(spp) + " paths per pixel)", "-",
                  "1", std::to_string(truth.seconds).substr(0, 5)});
    for (const MethodEntry& m : methodTable()) {
        if (m.name == "path") continue;
        if (const std::string why = m.unavailableReason(); !why.empty()) {
            std::fprintf(stderr, "lucent: gallery: %s cannot run here: %s\n", m.name.c_str(), why.c_str());
            continue;
        }
        std::fprintf(stderr, "lucent: gallery: %s: %s\n", name.c_str(), m.name.c_str());
        const std::unique_ptr<Method> method = m.createDefault();
        stopwatch.restart();
        const Image image = renderWith(m, *method, loaded, settings);
        const double seconds = stopwatch.seconds();
        const NoisyReferenceError e = luminanceRelativeRmse(image, truth.a, truth.b);
        char error[32], mean[32], time[32];
        std::snprintf(error, sizeof error, "%.1f%%", 100.0 * e.debiased);
        std::snprintf(mean, sizeof mean, "%.2f", meanLuminance(image) / meanLuminance(truth.mean));
        std::snprintf(time, sizeof time, "%.2f", seconds);
        out.tableRow({picture(m.name, image), m.name, error, mean, time});
    }
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"The gallery: every method on the bundled scenes beside the path tracer, with error and time"};
    std::vector<std::string> scenes;
    int size = 128, spp = 256;
    std::string imagesDir = "docs/images/gallery", recordFile;
    app.add_option("scenes", scenes,
                   "Scene files (default: the bundled bunny, sphere, cube, torus cube and layered cube)");
    app.add_option("--size", size, "Image width and height")->check(CLI::Range(8, 2048));
    app.add_option("--spp", spp, "Paths per pixel of each of the truth's two renders")->check(CLI::Range(1, 1 << 20));
    app.add_option("--images", imagesDir, "Folder for the PNGs");
    app.add_option("--record", recordFile, "Also write the gallery to this Markdown file (docs/gallery.md)");
    CLI11_PARSE(app, argc, argv);
    if (scenes.empty())
        for (const char* s : {"bunny", "sphere", "cube", "torus-cube", "layered-cube"})
            scenes.push_back(std::string(LUCENT_SOURCE_DIR) + "/models/" + s + ".json");
    try {
        ResultsRecord out(argc, argv);
        out.print(
            "Every method on the bundled scenes, beside `--method path` (full transport, the truth). ss and "
            "reference compute single scattering only: their error against full transport is the light scattered "
            "more than once, which lbl and mdom add. Each image of a scene is shown at the truth's exposure. "
            "Times are one render on this machine, without loading or preprocessing.\n");
        fs::create_directories(imagesDir);
        const fs::path base = recordFile.empty()
                                  ? fs::path(imagesDir)
                                  : fs::relative(fs::absolute(imagesDir), fs::absolute(recordFile).parent_path());
        for (const std::string& s : scenes) gallery(out, s, size, spp, imagesDir, base);
        if (!recordFile.empty()) out.write(recordFile);
    } catch (const Error& e) {
        std::fprintf(stderr, "lucent-bench-gallery: error: %s\n", e.what());
        return 1;
    }
    return 0;
}
