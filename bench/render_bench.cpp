// Render benchmark (thesis Tables 3.2 and 3.3): median frame time after warm-up
// of --method ss at 800x800 on Mesa's llvmpipe, against the sample count and the
// number of lights, and how many of the fragments the proxies generate carry a
// Gaussian above the cut-off; then the scattering at full, half and quarter
// resolution (DrawOptions::scatterScale), interleaved, with each one's error
// against --method reference.
//
//   build/bin/lucent-bench-render [SCENE] [--frames N] [--warmup N] [--scales-only]
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstdio>

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

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"Lucent render benchmark (thesis Tables 3.2 and 3.3)"};
    std::string sceneFile = std::string(LUCENT_SOURCE_DIR) + "/models/bunny.json";
    int frames = 15, warmup = 3, size = 800;
    std::string backendName;
    app.add_option("scene", sceneFile, "Scene whose first object is rendered");
    app.add_option("--frames", frames, "Timed frames per setting (median reported)");
    app.add_option("--warmup", warmup, "Untimed frames first");
    app.add_option("--size", size, "Viewport width and height");
    app.add_option("--backend", backendName, "osmesa or egl");
    bool scalesOnly = false;
    app.add_flag("--scales-only", scalesOnly, "Only the table of reduced scattering resolutions");
    std::string imagesDir;
    app.add_option("--images", imagesDir, "Write the reduced-resolution images and the reference there (PNG)");
    CLI11_PARSE(app, argc, argv);
    try {
        SceneDesc scene = parseScene(sceneFile);
        scene.camera.width = scene.camera.height = size;
        std::vector<std::string> warnings;
        const VolumeObject object(scene.objects.front(), warnings);
        const Bounds3 bounds = object.mesh().bounds();
        const auto context = OffscreenContext::create(parseGlBackend(backendName));
        const ViewSetup view = viewSetupFor(scene.camera, bounds);
        OffscreenFrame frame(size, size);
        std::printf("scene %s, %dx%d, %s (%s), median of %d frames after %d warm-up\n\n", sceneFile.c_str(), size,
                    size, context->backendName(), glRenderer().c_str(), frames,
                    warmup);

        auto measure = [&](const SampleSet& samples, int lights, ScatterFragments* counted) {
            ScatteringRenderer renderer;
            renderer.addObject(translucentObjectFor(object, samples));
            renderer.setLights(lightsAround(lights, bounds));
            const double seconds =
                medianFrameSeconds(warmup, frames, [&] { frame.bindAndClear(); }, [&] { renderer.draw(view); });
            if (counted) {
                // The proxies' fragments at full resolution (reduced, the upsampling's
                // own fragments would count): shaded, and those whose Gaussian is above
                // the cut-off (ScatterFragments).
                DrawOptions options;
                options.surface = false;
                options.scatterScale = 1;
                options.discardBelow = float(kDefaultGaussianCutoff);
                options.fragments = counted;
                frame.bindAndClear();
                renderer.draw(view, options);
            }
            return seconds;
        };
        auto samplesFor = [&](int count) {
            PreprocessSettings s;
            s.samples = count;
            std::fprintf(stderr, "preprocessing %d samples...\n", count);
            return checkSamplesBelong(object, preprocessObject(object, s), "in-memory samples of " + object.desc().name);
        };

        // The scattering at 1/1, 1/2 and 1/4 of the resolution, interleaved frame by
        // frame; each image against the reference, 2 px inside the silhouette and in all.
        {
            const SampleSet samples = samplesFor(50000);
            const std::vector<int> scales = {1, 2, 4};
            ScatteringRenderer renderer;
            renderer.addObject(translucentObjectFor(object, samples));
            scene.lights = lightsAround(1, bounds);
            renderer.setLights(scene.lights);
            std::vector<std::vector<double>> times(scales.size());
            std::vector<Image> images;
            for (int round = 0; round < warmup + frames; ++round)
                for (size_t k = 0; k < scales.size(); ++k) {
                    DrawOptions options;
                    options.surface = false;
                    options.scatterScale = scales[k];
                    frame.bindAndClear();
                    const double t = timeGlWork([&] { renderer.draw(view, options); });
                    if (round >= warmup) times[k].push_back(t);
                    if (round == 0) images.push_back(frame.read());
                }
            std::fprintf(stderr, "rendering the reference...\n");
            ReferenceSettings rs;
            rs.surface = false;
            const std::vector<VolumeObject> objects = loadObjects(scene, warnings);
            const Image reference = ReferenceRenderer(scene, objects).render(rs);
            std::printf("%zu samples, %d interleaved rounds, surface off; error: relative RMSE against --method reference\n\n"
                        "| scattering at | frame (ms) | vs full | error, 2 px inside | error, all pixels |\n"
                        "|---|---:|---:|---:|---:|\n",
                        samples.size(), frames);
            for (size_t k = 0; k < scales.size(); ++k) {
                const double t = median(times[k]);
                std::printf("| 1/%d | %.1f | %.2fx | %.2f%% | %.2f%% |\n", scales[k], 1e3 * t, median(times[0]) / t,
                            100.0 * compareImages(images[k], reference, 2).relativeRmse,
                            100.0 * compareImages(images[k], reference).relativeRmse);
            }
            std::printf("\n");
            std::fflush(stdout);
            if (!imagesDir.empty()) {
                const float exposure = autoExposure(reference);
                writeImage(imagesDir + "/reference.png", reference, exposure);
                for (size_t k = 0; k < scales.size(); ++k)
                    writeImage(imagesDir + "/scatter-1-" + std::to_string(scales[k]) + ".png", images[k], exposure);
            }
            if (scalesOnly) return 0;
        }
        std::printf("frames at the default scattering resolution (by the samples' radius on screen); useful "
                    "fragments at full resolution "
                    "(useful: of the fragments shaded; of llvmpipe's fragment shader invocations, counted in "
                    "4x4 blocks)\n\n"
                    "| samples | frame (ms) | fps | useful fragments | of invocations |\n|---:|---:|---:|---:|---:|\n");
        for (int count : {25000, 50000, 100000}) {
            const SampleSet samples = samplesFor(count);
            ScatterFragments fragments;
            const double t = measure(samples, 1, &fragments);
            auto share = [](unsigned long long part, unsigned long long whole) {
                return whole > 0 ? 100.0 * double(part) / double(whole) : 0.0;
            };
            std::printf("| %zu | %.1f | %.1f | %.1f%% | %.1f%% |\n", samples.size(), 1e3 * t, 1.0 / t,
                        share(fragments.kept, fragments.shaded), share(fragments.kept, fragments.invocations));
            std::fflush(stdout);
        }
        // The light sweep interleaves the settings frame by frame, so that a slow
        // spell of this shared machine lands on every setting alike.
        const SampleSet samples = samplesFor(58000);
        const std::vector<int> lightCounts = {1, 2, 4, 8, 16};
        std::vector<std::unique_ptr<ScatteringRenderer>> renderers;
        for (int lights : lightCounts) {
            renderers.push_back(std::make_unique<ScatteringRenderer>());
            renderers.back()->addObject(translucentObjectFor(object, samples));
            renderers.back()->setLights(lightsAround(lights, bounds));
        }
        // Three cases: lights that stay put (an isotropic medium then reuses the light
        // each sample receives, traced once), and lights that change every frame,
        // read from the SH again (--light sh) or traced again.
        std::vector<std::vector<double>> still(lightCounts.size()), moving(lightCounts.size()),
            traced(lightCounts.size());
        for (int round = 0; round < warmup + 2 * frames; ++round)
            for (size_t k = 0; k < lightCounts.size(); ++k)
                for (int kind = 0; kind < 3; ++kind) {
                    if (kind > 0) renderers[k]->setLights(lightsAround(lightCounts[k], bounds));
                    DrawOptions options;
                    options.tracedLight = kind != 1;
                    frame.bindAndClear();
                    const double t = timeGlWork([&] { renderers[k]->draw(view, options); });
                    if (round >= warmup) (kind == 0 ? still : kind == 1 ? moving : traced)[k].push_back(t);
                }
        std::printf("\n%zu samples, %d interleaved rounds:\n\n"
                    "| lights | still lights: frame (ms) | vs 1 light | changing every frame, SH: frame (ms) | vs 1 "
                    "light | changing every frame, traced: frame (ms) | vs 1 light |\n"
                    "|---:|---:|---:|---:|---:|---:|---:|\n",
                    samples.size(), 2 * frames);
        const double oneStill = median(still[0]), oneMoving = median(moving[0]), oneTraced = median(traced[0]);
        for (size_t k = 0; k < lightCounts.size(); ++k) {
            const double s = median(still[k]), m = median(moving[k]), t = median(traced[k]);
            std::printf("| %d | %.1f | %+.1f%% | %.1f | %+.1f%% | %.1f | %+.1f%% |\n", lightCounts[k], 1e3 * s,
                        100.0 * (s / oneStill - 1.0), 1e3 * m, 100.0 * (m / oneMoving - 1.0), 1e3 * t,
                        100.0 * (t / oneTraced - 1.0));
        }
    } catch (const Error& e) {
        std::fprintf(stderr, "lucent-bench-render: error: %s\n", e.what());
        return 1;
    }
    return 0;
}
