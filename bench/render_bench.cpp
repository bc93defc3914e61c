// Render benchmark (thesis Tables 3.2 and 3.3): median frame time after warm-up
// of --method ss at 800x800 on Mesa's llvmpipe, against the sample count and the
// number of lights, and how many of the fragments the proxies generate carry a
// Gaussian above the cut-off; then the scattering at full, half and quarter
// resolution (DrawOptions::scatterScale), interleaved, with each one's error
// against --method reference.
//
//   build/bin/lucent-bench-render [SCENE] [--frames N] [--warmup N] [--scales-only]
//                                 [--record docs/results/render.md]
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>

#include "bench/results_record.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/loaded_scene.h"
#include "core/statistics.h"
#include "core/scene.h"
#include "core/volume_object.h"
#include "core/image_compare.h"
#include "preprocess/preprocessor.h"
#include "reference/reference_renderer.h"
#include "runtime/offscreen_context.h"
#include "runtime/offscreen_frame.h"
#include "runtime/scattering_renderer.h"

using namespace lucent;

namespace {

// n lights at one place, each with 1/n of the power: the image, and so the
// fragment work, stays the same, and the sweep measures what each light costs.
// (Lights in different places also change which samples are lit at all, and with
// them the number of fragments; that is the scene's cost, not the light's.)
std::vector<Light> lightsAround(int count, const Bounds3& bounds) {
    const double radius = 2.0 * bounds.diagonal();
    Light l;
    l.position = bounds.center() + radius * Vec3(0.3, 0.8, 1.0);
    l.power = Rgb(1.0, 0.9, 0.8) * (4.0 * radius * radius / count);
    return std::vector<Light>(size_t(count), l);
}

// What every table of the benchmark shares: the object, the view, the target,
// how many frames to time, and the record the tables go to.
struct Bench {
    const SceneDesc& scene;
    const VolumeObject& object;
    Bounds3 bounds;
    ViewSetup view;
    OffscreenFrame& frame;
    int frames, warmup;
    ResultsRecord& out;

    SampleSet samplesFor(int count) const {
        PreprocessSettings s;
        s.samples = count;
        std::fprintf(stderr, "preprocessing %d samples...\n", count);
        return checkSamplesBelong(object, preprocessObject(object, s), "in-memory samples of " + object.desc().name);
    }
};

// The scattering at 1/1, 1/2 and 1/4 of the resolution, interleaved frame by
// frame; each image against the reference, 2 px inside the silhouette and in all.
void scalesTable(const Bench& b, const std::string& imagesDir) {
    const SampleSet samples = b.samplesFor(50000);
    const std::vector<int> scales = {1, 2, 4};
    SceneDesc scene = b.scene;
    scene.lights = lightsAround(1, b.bounds);
    ScatteringRenderer renderer;
    renderer.addObject(translucentObjectFor(b.object, samples));
    renderer.setLights(scene.lights);
    std::vector<std::vector<double>> times(scales.size());
    std::vector<Image> images;
    for (int round = 0; round < b.warmup + b.frames; ++round)
        for (size_t k = 0; k < scales.size(); ++k) {
            DrawOptions options;
            options.surface = false;
            options.scatterScale = scales[k];
            b.frame.bindAndClear();
            const double t = timeGlWork([&] { renderer.draw(b.view, options); });
            if (round >= b.warmup) times[k].push_back(t);
            if (round == 0) images.push_back(b.frame.read());
        }
    std::fprintf(stderr, "rendering the reference...\n");
    ReferenceSettings rs;
    rs.surface = false;
    std::vector<std::string> warnings;
    const std::vector<VolumeObject> objects = loadObjects(scene, warnings);
    const Image reference = ReferenceRenderer(scene, objects).render(rs);
    b.out.print("%zu samples, %d interleaved rounds, surface off; error: relative RMSE against --method reference\n\n",
                samples.size(), b.frames);
    b.out.tableHeader({"scattering at", "frame (ms)", "vs full", "error, 2 px inside", "error, all pixels"},
                      {false, true, true, true, true});
    for (size_t k = 0; k < scales.size(); ++k) {
        const double t = median(times[k]);
        b.out.print("| 1/%d | %.1f | %.2fx | %.2f%% | %.2f%% |\n", scales[k], 1e3 * t, median(times[0]) / t,
                    100.0 * compareImages(images[k], reference, 2).relativeRmse,
                    100.0 * compareImages(images[k], reference).relativeRmse);
    }
    b.out.print("\n");
    if (!imagesDir.empty()) {
        const float exposure = autoExposure(reference);
        writeImage(imagesDir + "/reference.png", reference, exposure);
        for (size_t k = 0; k < scales.size(); ++k)
            writeImage(imagesDir + "/scatter-1-" + std::to_string(scales[k]) + ".png", images[k], exposure);
    }
}

// Thesis Table 3.2: the frame against the sample count, and the share of the
// proxies' fragments that carry a Gaussian above the cut-off.
void samplesTable(const Bench& b) {
    b.out.print(
        "frames at the default scattering resolution (by the samples' radius on screen); useful fragments "
        "at full resolution (useful: of the fragments shaded; of llvmpipe's fragment shader invocations, "
        "counted in 4x4 blocks)\n\n");
    b.out.tableHeader({"samples", "frame (ms)", "fps", "useful fragments", "of invocations"},
                      std::vector<bool>(5, true));
    for (int count : {25000, 50000, 100000}) {
        const SampleSet samples = b.samplesFor(count);
        ScatteringRenderer renderer;
        renderer.addObject(translucentObjectFor(b.object, samples));
        renderer.setLights(lightsAround(1, b.bounds));
        const double t = medianFrameSeconds(
            b.warmup, b.frames, [&] { b.frame.bindAndClear(); }, [&] { renderer.draw(b.view); });
        // The proxies' fragments at full resolution (reduced, the upsampling's own
        // fragments would count): shaded, and those whose Gaussian is above the
        // cut-off (ScatterFragments).
        ScatterFragments fragments;
        DrawOptions options;
        options.surface = false;
        options.scatterScale = 1;
        options.discardBelow = float(kDefaultGaussianCutoff);
        options.fragments = &fragments;
        b.frame.bindAndClear();
        renderer.draw(b.view, options);
        auto share = [](unsigned long long part, unsigned long long whole) {
            return whole > 0 ? 100.0 * double(part) / double(whole) : 0.0;
        };
        b.out.print("| %zu | %.1f | %.1f | %.1f%% | %.1f%% |\n", samples.size(), 1e3 * t, 1.0 / t,
                    share(fragments.kept, fragments.shaded), share(fragments.kept, fragments.invocations));
    }
}

// Thesis Table 3.3: the frame against the number of lights, in three cases:
// lights that stay put (an isotropic medium then reuses the light each sample
// receives, traced once), and lights that change every frame, read from the SH
// again (--light sh) or traced again. The settings are interleaved frame by
// frame, so that a slow spell of this shared machine lands on every one alike.
void lightsTable(const Bench& b) {
    const SampleSet samples = b.samplesFor(58000);
    const std::vector<int> lightCounts = {1, 2, 4, 8, 16};
    std::vector<std::unique_ptr<ScatteringRenderer>> renderers;
    for (int lights : lightCounts) {
        renderers.push_back(std::make_unique<ScatteringRenderer>());
        renderers.back()->addObject(translucentObjectFor(b.object, samples));
        renderers.back()->setLights(lightsAround(lights, b.bounds));
    }
    std::vector<std::vector<double>> still(lightCounts.size()), moving(lightCounts.size()), traced(lightCounts.size());
    for (int round = 0; round < b.warmup + 2 * b.frames; ++round)
        for (size_t k = 0; k < lightCounts.size(); ++k)
            for (int kind = 0; kind < 3; ++kind) {
                if (kind > 0) renderers[k]->setLights(lightsAround(lightCounts[k], b.bounds));
                DrawOptions options;
                options.tracedLight = kind != 1;
                b.frame.bindAndClear();
                const double t = timeGlWork([&] { renderers[k]->draw(b.view, options); });
                if (round >= b.warmup) (kind == 0 ? still : kind == 1 ? moving : traced)[k].push_back(t);
            }
    b.out.print("\n%zu samples, %d interleaved rounds:\n\n", samples.size(), 2 * b.frames);
    b.out.tableHeader({"lights", "still lights: frame (ms)", "vs 1 light", "changing every frame, SH: frame (ms)",
                       "vs 1 light", "changing every frame, traced: frame (ms)", "vs 1 light"},
                      std::vector<bool>(7, true));
    const double oneStill = median(still[0]), oneMoving = median(moving[0]), oneTraced = median(traced[0]);
    for (size_t k = 0; k < lightCounts.size(); ++k) {
        const double s = median(still[k]), m = median(moving[k]), t = median(traced[k]);
        b.out.print("| %d | %.1f | %+.1f%% | %.1f | %+.1f%% | %.1f | %+.1f%% |\n", lightCounts[k], 1e3 * s,
                    100.0 * (s / oneStill - 1.0), 1e3 * m, 100.0 * (m / oneMoving - 1.0), 1e3 * t,
                    100.0 * (t / oneTraced - 1.0));
    }
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"Lucent render benchmark (thesis Tables 3.2 and 3.3)"};
    std::string sceneFile = std::string(LUCENT_SOURCE_DIR) + "/models/bunny.json";
    int frames = 15, warmup = 3, size = 800;
    std::string backendName;
    app.add_option("scene", sceneFile, "Scene whose first object is rendered");
    app.add_option("--frames", frames, "Timed frames per setting (median reported)")->check(CLI::Range(1, 10000));
    app.add_option("--warmup", warmup, "Untimed frames first")->check(CLI::Range(0, 10000));
    app.add_option("--size", size, "Viewport width and height")->check(CLI::Range(8, 8192));
    app.add_option("--backend", backendName, "osmesa or egl");
    bool scalesOnly = false;
    app.add_flag("--scales-only", scalesOnly, "Only the table of reduced scattering resolutions");
    std::string imagesDir;
    app.add_option("--images", imagesDir, "Write the reduced-resolution images and the reference there (PNG)");
    std::string recordFile;
    app.add_option("--record", recordFile, "Also write the results to this Markdown file (docs/results/)");
    CLI11_PARSE(app, argc, argv);
    try {
        if (!recordFile.empty()) checkWritable(recordFile);
        ResultsRecord out(argc, argv);
        SceneDesc scene = parseScene(sceneFile);
        scene.camera.width = scene.camera.height = size;
        std::vector<std::string> warnings;
        const VolumeObject object(scene.objects.front(), warnings);
        const Bounds3 bounds = object.mesh().bounds();
        const auto context = OffscreenContext::create(parseGlBackend(backendName));
        OffscreenFrame frame(size, size);
        out.addDevice(std::string(context->backendName()) + ": " + glRenderer());
        out.print("scene %s, %dx%d, median of %d frames after %d warm-up\n\n",
                  std::filesystem::path(sceneFile).filename().c_str(), size, size, frames, warmup);
        const Bench bench{scene, object, bounds, viewSetupFor(scene.camera, bounds), frame, frames, warmup, out};
        scalesTable(bench, imagesDir);
        if (!scalesOnly) {
            samplesTable(bench);
            lightsTable(bench);
        }
        if (!recordFile.empty()) out.write(recordFile);
    } catch (const Error& e) {
        std::fprintf(stderr, "lucent-bench-render: error: %s\n", e.what());
        return 1;
    }
    return 0;
}
