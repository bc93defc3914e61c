// The peer benchmark: Lucent beside Blender's Cycles, the production path
// tracer a user of this machine would pick instead, on the wax bunny (the
// scene's first object and light, sigma_t 8, albedo 0.95, g 0, index-matched,
// seen from 5 units, framed to 90% of the height). Cycles renders on two
// threads, as Lucent does here (bench/cycles_peer.h).
//
//   build/bin/lucent-bench-peer single [SCENE] [--size 256] [--samples 1,2,4,...]
//       --method ss against --method reference (exact single scattering) beside
//       Cycles' single scattering: relative RMSE 2 px inside the silhouette and
//       render time (ss: the median frame after warm-up, preprocessing apart;
//       Cycles: its render call, Blender's start and scene set-up apart); then,
//       at ss's error, how many samples Cycles needs and how long it takes.
//   build/bin/lucent-bench-peer full [SCENE] [--sizes 256,800] [--samples 16,64,256]
//                                    [--truth-samples 1024] [--spp 16,64,256]
//       Full transport: lbl, mdom and path against Cycles' full transport at
//       truth-samples (two renders of half as many with their own seeds, whose
//       noise is taken out: core/image_compare.h), luminance relative RMSE 2 px
//       inside the silhouette. Each method's first image (preprocessing, solve,
//       frame) and a new view (the camera turned 40 degrees about the object,
//       samples and solve kept: its frame) timed apart, and the time Cycles
//       takes to the same error (below).
//
// Common options: [--distance 5] [--frames N] [--warmup N] [--blender blender]
// [--out DIR] [--record FILE]. Cycles comes from Debian's `blender`
// (scripts/install-deps.sh --peer); the tests never need it.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <glm/gtc/matrix_transform.hpp>

#include "bench/cycles_peer.h"
#include "bench/results_record.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/image_compare.h"
#include "core/loaded_scene.h"
#include "core/scene.h"
#include "core/stopwatch.h"
#include "core/volume_object.h"
#include "hybrid/mdom_scattering.h"
#include "hybrid/multiple_scattering.h"
#include "methods/method_table.h"
#include "preprocess/preprocessor.h"
#include "reference/path_tracer.h"
#include "reference/reference_renderer.h"
#include "runtime/offscreen_context.h"
#include "runtime/offscreen_frame.h"
#include "runtime/scattering_renderer.h"
#include "runtime/ss_method.h"

using namespace lucent;

namespace {

double luminance(const glm::vec3& c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }

struct PeerOptions {
    std::string sceneFile = std::string(LUCENT_SOURCE_DIR) + "/models/bunny.json";
    double distance = 5.0;
    int frames = 15, warmup = 3;
    std::string blender = "blender", outDir = "peer-bench", recordFile;
};

// The scene: the scene's first object and first light, grey sigma_t 8
// and albedo 0.95, the camera moved to `distance` along its own direction and
// aimed at the object with a field of view that frames it, no surface term.
LoadedScene peerScene(const PeerOptions& o, int size) {
    SceneDesc s = parseScene(o.sceneFile);
    s.objects.resize(1);
    s.lights.resize(1);
    s.objects[0].medium.sigmaT = Rgb(8.0);
    s.objects[0].medium.albedo = Rgb(0.95);
    s.objects[0].medium.g = 0.0;
    s.render.surface = false;
    const double grey = (s.lights[0].power.r + s.lights[0].power.g + s.lights[0].power.b) / 3.0;
    s.lights[0].power = Rgb(grey);
    LoadedScene scene = loadScene(s, false);
    const Bounds3 bounds = scene.bounds();
    Camera& c = scene.desc.camera;
    c.position = c.target + o.distance * glm::normalize(c.position - c.target);
    c.width = c.height = size;
    // The bounding sphere fills 90% of the height.
    c.target = bounds.center();
    const double radius = 0.5 * bounds.diagonal();
    c.fovYDegrees = 2.0 * std::asin(std::min(1.0, radius / o.distance)) * 180.0 / kPi / 0.9;
    return scene;
}

CyclesScene cyclesSceneOf(const LoadedScene& scene, int volumeBounces) {
    const VolumeObject& object = scene.objects.front();
    return {object.mesh(), object.desc().medium, scene.desc.lights, scene.desc.camera, volumeBounces};
}

// The camera turned by degrees about the up axis through its target.
Camera turned(Camera c, double degrees) {
    const glm::dmat4 turn = glm::rotate(glm::dmat4(1.0), glm::radians(degrees), glm::normalize(c.up));
    c.position = c.target + Vec3(turn * glm::dvec4(c.position - c.target, 0.0));
    return c;
}

// ---- single: ss against the exact reference, beside Cycles' single scattering

void single(const PeerOptions& o, int size, const std::vector<int>& samples, ResultsRecord& out) {
    LoadedScene scene = peerScene(o, size);
    const VolumeObject& object = scene.objects.front();
    Stopwatch stopwatch;
    attachSamples(scene, {preprocessObject(object, qualityPreset("default"))});
    const double preprocessSeconds = stopwatch.seconds();

    stopwatch.restart();
    ReferenceSettings rs;
    rs.surface = false;
    const Image reference = ReferenceRenderer(scene.desc, scene.objects).render(rs);
    const double referenceSeconds = stopwatch.seconds();

    const auto context = OffscreenContext::create(GlBackend::Auto);
    out.addDevice(std::string(context->backendName()) + ": " + glRenderer());
    OffscreenFrame frame(size, size);
    ScatteringRenderer renderer;
    renderer.addObject(translucentObjectFor(object, scene.samples.front()));
    renderer.setLights(scene.desc.lights);
    const ViewSetup view = viewSetupFor(scene.desc.camera, scene.bounds());
    DrawOptions options;
    options.surface = false;
    const double ssSeconds = medianFrameSeconds(
        o.warmup, o.frames, [&] { frame.bindAndClear(); }, [&] { renderer.draw(view, options); });
    const double ssError = compareImages(frame.read(), reference, 2).relativeRmse;

    std::vector<CyclesRender> renders;
    for (int n : samples) renders.push_back({"n" + std::to_string(n), n, 1});
    const std::vector<CyclesImage> cycles =
        renderWithCycles(o.blender, std::filesystem::absolute(o.outDir) / "single", cyclesSceneOf(scene, 0), renders);

    out.print(
        "scene %s's first object and light, sigma_t 8, albedo 0.95, %dx%d, camera %.2f away; "
        "error: relative RMSE 2 px inside the silhouette against --method reference (%.2f s)\n\n",
        std::filesystem::path(o.sceneFile).filename().c_str(), size, size, o.distance, referenceSeconds);
    out.tableHeader({"renderer", "setting", "error", "render time (s)"}, {false, false, true, true});
    out.print("| ss | default quality (preprocessing %.1f s apart), median of %d frames | %.2f%% | %.4f |\n",
              preprocessSeconds, o.frames, 100.0 * ssError, ssSeconds);
    const CyclesImage* equal = nullptr;
    for (const CyclesImage& c : cycles) {
        const ImageError e = compareImages(c.image, reference, 2);
        out.print("| Cycles | %d samples per pixel | %.2f%% (mean ratio %.3f) | %.4f |\n", c.render.samples,
                  100.0 * e.relativeRmse, e.meanRatio, c.seconds);
        if (!equal && e.relativeRmse <= ssError) equal = &c;
    }
    if (equal)
        out.print("\nAt ss's error (%.2f%%), Cycles needs %d samples per pixel: %.4f s against ss's %.4f s (%.1fx).\n",
                  100.0 * ssError, equal->render.samples, equal->seconds, ssSeconds, equal->seconds / ssSeconds);
    else
        out.print("\nNo sample count swept brings Cycles to ss's error (%.2f%%).\n", 100.0 * ssError);
}

// ---- full: lbl, mdom and path against Cycles' full transport

struct FullSettings {
    std::vector<int> sizes{256, 800}, samples{16, 64, 256}, spp{16, 64, 256};
    int truthSamples = 1024;
};

// One Lucent row: its error against Cycles' truth and its two times.
struct Measured {
    std::string method, setting;
    double error = 0.0, meanRatio = 0.0, firstImage = 0.0, newView = 0.0;
};

// Cycles' truth (two halves) and its sweep, with every image kept to the
// truth's pixels 2 px inside the silhouette (the others zero, which the
// luminance metric skips).
struct CyclesRun {
    Image truthA, truthB;
    std::vector<CyclesImage> sweep;
    std::vector<bool> interior;
    Image masked(Image image) const {
        if (image.pixels.size() != interior.size())
            throw Error("an image of " + std::to_string(image.width) + "x" + std::to_string(image.height) +
                        " pixels against Cycles' truth of another size");
        for (size_t i = 0; i < image.pixels.size(); ++i)
            if (!interior[i]) image.pixels[i] = glm::vec3(0.0f);
        return image;
    }
    double error(const Image& image) const { return luminanceRelativeRmse(masked(image), truthA, truthB).debiased; }
    // The image's luminance over the truth's, summed over the compared pixels: a bias shows here, noise does not.
    double meanRatio(const Image& image) const {
        double test = 0.0, truth = 0.0;
        for (size_t i = 0; i < image.pixels.size(); ++i)
            if (interior[i]) {
                test += luminance(image.pixels[i]);
                truth += 0.5 * (luminance(truthA.pixels[i]) + luminance(truthB.pixels[i]));
            }
        return test / truth;
    }
};

CyclesRun runCycles(const PeerOptions& o, const FullSettings& f, const LoadedScene& scene) {
    const int half = std::max(1, f.truthSamples / 2);
    std::vector<CyclesRender> renders{{"truth-a", half, 1}, {"truth-b", half, 2}};
    for (int n : f.samples) renders.push_back({"n" + std::to_string(n), n, uint64_t(renders.size() + 1)});
    const std::filesystem::path dir =
        std::filesystem::absolute(o.outDir) / ("full-" + std::to_string(scene.desc.camera.width));
    // Cycles' volume bounces at most: beyond them its paths end (Lucent's do not).
    std::vector<CyclesImage> images = renderWithCycles(o.blender, dir, cyclesSceneOf(scene, 1024), renders);
    CyclesRun run;
    Image truth = images[0].image;
    for (size_t i = 0; i < truth.pixels.size(); ++i)
        truth.pixels[i] = 0.5f * (images[0].image.pixels[i] + images[1].image.pixels[i]);
    run.interior = interiorPixels(truth, 2);
    if (std::find(run.interior.begin(), run.interior.end(), true) == run.interior.end())
        throw Error((dir / "cycles-truth-a.pfm").string(), "Cycles' truth lights no pixel 2 px inside the object");
    run.truthA = run.masked(images[0].image);
    run.truthB = run.masked(images[1].image);
    run.sweep.assign(images.begin() + 2, images.end());
    return run;
}

// The frame of a new view with the samples and grid kept, on one context: the
// median after warm-up. towards: for mdom, the grid baked for the new eye (part
// of a new view's cost); empty for lbl, whose grid holds for every view.
double newViewSeconds(const PeerOptions& o, const LoadedScene& scene, const ScatteringGrid& lblGrid,
                      const hybrid::MdomSolution* mdom) {
    const Camera camera = turned(scene.desc.camera, 40.0);
    const auto context = OffscreenContext::create(GlBackend::Auto);
    OffscreenFrame frame(camera.width, camera.height);
    ScatteringRenderer renderer;
    renderer.addObject(translucentObjectFor(scene.objects.front(), scene.samples.front()));
    setSsLights(renderer, scene, SsOptions{});
    if (!mdom) renderer.addScatteringGrid(lblGrid);
    const ViewSetup view = viewSetupFor(camera, scene.bounds());
    DrawOptions options;
    options.surface = false;
    return medianFrameSeconds(
        o.warmup, o.frames, [&] { frame.bindAndClear(); },
        [&] {
            if (mdom) {
                renderer.clearScatteringGrids();
                renderer.addScatteringGrid(mdom->towards(camera.position));
            }
            renderer.draw(view, options);
        });
}

// lbl and mdom with their default options, as `lucent render` solves them.
std::vector<Measured> gridMethods(const PeerOptions& o, LoadedScene& scene, double preprocessSeconds,
                                  const CyclesRun& cycles) {
    MethodSettings settings;
    settings.surface = false;
    std::string backend;
    const std::vector<Light> lights = scene.lightsWithEnvironment(0);
    std::vector<Measured> rows;

    const MethodOptions lblOptions(findMethod("lbl").options);
    Stopwatch stopwatch;
    hybrid::MultipleScattering lbl;
    hybrid::HybridSettings hs;
    hs.resolution = lblOptions.integer("grid");
    const ScatteringGrid lblGrid = lbl.solve(scene.objects.front(), lights, hs);
    const double lblSolve = stopwatch.seconds();
    stopwatch.restart();
    const Image lblImage = renderSingleScattering(scene, settings, SsOptions{}, {lblGrid}, backend);
    const double lblFrame = stopwatch.seconds();
    rows.push_back({"lbl",
                    "grid " + std::to_string(hs.resolution) + ", solve " + std::to_string(lblSolve).substr(0, 4) + " s",
                    cycles.error(lblImage), cycles.meanRatio(lblImage), preprocessSeconds + lblSolve + lblFrame,
                    newViewSeconds(o, scene, lblGrid, nullptr)});

    const MethodOptions mdomOptions(findMethod("mdom").options);
    stopwatch.restart();
    hybrid::MdomScattering mdom;
    hybrid::MdomSettings ms;
    ms.resolution = mdomOptions.integer("grid");
    ms.directions = mdomOptions.integer("directions");
    ms.bands = int(std::lround(std::sqrt(double(mdomOptions.integer("moments")))));
    const hybrid::MdomSolution solution = mdom.solve(scene.objects.front(), lights, ms);
    const ScatteringGrid mdomGrid = solution.towards(scene.desc.camera.position);
    const double mdomSolve = stopwatch.seconds();
    stopwatch.restart();
    const Image mdomImage = renderSingleScattering(scene, settings, SsOptions{}, {mdomGrid}, backend);
    const double mdomFrame = stopwatch.seconds();
    rows.push_back({"mdom",
                    "grid " + std::to_string(ms.resolution) + ", " + std::to_string(ms.directions) +
                        " directions, solve " + std::to_string(mdomSolve).substr(0, 4) + " s",
                    cycles.error(mdomImage), cycles.meanRatio(mdomImage), preprocessSeconds + mdomSolve + mdomFrame,
                    newViewSeconds(o, scene, lblGrid, &solution)});
    return rows;
}

// The path tracer at each count of paths per pixel: its first image builds the
// tracer (the objects' ray casters) too; a new view is its render alone.
std::vector<Measured> pathTracer(const FullSettings& f, const LoadedScene& scene, const CyclesRun& cycles) {
    std::vector<Measured> rows;
    Stopwatch stopwatch;
    const PathTracer tracer(scene.desc, scene.objects);
    const double build = stopwatch.seconds();
    for (int spp : f.spp) {
        PathSettings settings;
        settings.samplesPerPixel = spp;
        settings.surface = false;
        stopwatch.restart();
        const Image image = tracer.render(settings).mean;
        const double seconds = stopwatch.seconds();
        rows.push_back({"path", std::to_string(spp) + " paths per pixel", cycles.error(image), cycles.meanRatio(image),
                        build + seconds, seconds});
    }
    return rows;
}

// Cycles' time to an error, from its sweep's largest sample count n: Cycles is
// unbiased, so its error falls as 1 / sqrt(samples) and its time grows as the
// samples: t(e) = t(n) (e(n) / e)^2.
struct CyclesLaw {
    double error = 0.0, seconds = 0.0;
    double secondsTo(double e) const { return seconds * (error / e) * (error / e); }
};

void full(const PeerOptions& o, const FullSettings& f, ResultsRecord& out) {
    out.print(
        "scene %s's first object and light: sigma_t 8, albedo 0.95, g 0, index-matched, camera %.2f away. "
        "Cycles' truth: %d samples as two renders of %d with their own seeds, its noise taken out "
        "(core/image_compare.h). Error: luminance relative RMSE 2 px inside the silhouette against it. "
        "First image: preprocessing (default quality, once for every size), solve and frame, the scene's loading "
        "apart. New view: the camera turned 40 degrees, samples and solve kept; the median of %d frames after %d "
        "(lbl, mdom: its frame, with mdom's grid baked for the new eye; path: its render). Cycles' time to an error "
        "comes from its largest sample count (time x (its error / the error)^2); its time is its render call, "
        "the same for a new view.\n",
        std::filesystem::path(o.sceneFile).filename().c_str(), o.distance, f.truthSamples, f.truthSamples / 2, o.frames,
        o.warmup);
    // The samples do not depend on the image's size: made once, for the first.
    std::optional<SampleSet> samples;
    double preprocessSeconds = 0.0;
    for (int size : f.sizes) {
        LoadedScene scene = peerScene(o, size);
        if (!samples) {
            Stopwatch stopwatch;
            samples = preprocessObject(scene.objects.front(), qualityPreset("default"));
            preprocessSeconds = stopwatch.seconds();
        }
        attachSamples(scene, {*samples});
        const CyclesRun cycles = runCycles(o, f, scene);

        std::vector<Measured> rows = gridMethods(o, scene, preprocessSeconds, cycles);
        for (Measured& m : pathTracer(f, scene, cycles)) rows.push_back(std::move(m));

        out.print("\n### %dx%d\n\n", size, size);
        out.tableHeader({"renderer", "setting", "error", "mean ratio", "error x sqrt(samples)", "render time (s)"},
                        {false, false, true, true, true, true});
        CyclesLaw law;
        for (const CyclesImage& c : cycles.sweep) {
            const double e = cycles.error(c.image);
            out.print("| Cycles | %d samples per pixel | %.2f%% | %.3f | %.3f | %.3f |\n", c.render.samples, 100.0 * e,
                      cycles.meanRatio(c.image), e * std::sqrt(double(c.render.samples)), c.seconds);
            law = {e, c.seconds};
        }
        out.print("\n");
        out.tableHeader({"method", "setting", "error", "mean ratio", "first image (s)", "new view (s)",
                         "Cycles to that error (s)", "first image: x Cycles", "new view: x Cycles"},
                        {false, false, true, true, true, true, true, true, true});
        for (const Measured& m : rows) {
            if (!(m.error > 0.0)) {  // the truth too noisy to tell (--truth-samples)
                out.print("| %s | %s | below the truth's noise | %.3f | %.2f | %.3f | - | - | - |\n", m.method.c_str(),
                          m.setting.c_str(), m.meanRatio, m.firstImage, m.newView);
                continue;
            }
            const double cyclesSeconds = law.secondsTo(m.error);
            out.print("| %s | %s | %.2f%% | %.3f | %.2f | %.3f | %.2f | %.2f | %.1f |\n", m.method.c_str(),
                      m.setting.c_str(), 100.0 * m.error, m.meanRatio, m.firstImage, m.newView, cyclesSeconds,
                      cyclesSeconds / m.firstImage, cyclesSeconds / m.newView);
        }
    }
}

void commonOptions(CLI::App& app, PeerOptions& o) {
    app.add_option("scene", o.sceneFile, "Scene whose first object and light are rendered");
    app.add_option("--distance", o.distance, "Camera distance from its target")->check(CLI::Range(1e-3, 1e6));
    app.add_option("--frames", o.frames, "Timed frames (median reported)")->check(CLI::Range(1, 10000));
    app.add_option("--warmup", o.warmup, "Untimed frames first")->check(CLI::Range(0, 10000));
    app.add_option("--blender", o.blender, "The Blender program (Debian's blender package)");
    app.add_option("--out", o.outDir, "Directory for the images and Cycles' scene");
    app.add_option("--record", o.recordFile, "Also write the results to this Markdown file (docs/results/)");
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"Lucent peer benchmark: Lucent beside Blender's Cycles at equal error"};
    app.require_subcommand(1);
    PeerOptions singleOptions, fullOptions;
    fullOptions.frames = 5;
    fullOptions.warmup = 1;
    int singleSize = 256;
    std::vector<int> singleSamples{1, 2, 4, 8, 16, 32, 64, 128, 256};
    FullSettings f;

    CLI::App* singleCommand = app.add_subcommand("single", "ss against the exact reference, beside Cycles");
    commonOptions(*singleCommand, singleOptions);
    singleCommand->add_option("--size", singleSize, "Image width and height")->check(CLI::Range(8, 4096));
    singleCommand->add_option("--samples", singleSamples, "Cycles' samples per pixel swept")
        ->delimiter(',')
        ->check(CLI::Range(1, 1 << 20));

    CLI::App* fullCommand = app.add_subcommand("full", "lbl, mdom and path against Cycles' full transport");
    commonOptions(*fullCommand, fullOptions);
    fullCommand->add_option("--sizes", f.sizes, "Image widths and heights")->delimiter(',')->check(CLI::Range(8, 4096));
    fullCommand->add_option("--samples", f.samples, "Cycles' samples per pixel swept")
        ->delimiter(',')
        ->check(CLI::Range(1, 1 << 20));
    fullCommand->add_option("--truth-samples", f.truthSamples, "Cycles' samples per pixel of its truth")
        ->check(CLI::Range(2, 1 << 20));
    fullCommand->add_option("--spp", f.spp, "The path tracer's paths per pixel swept")
        ->delimiter(',')
        ->check(CLI::Range(1, 1 << 20));
    CLI11_PARSE(app, argc, argv);

    const PeerOptions& o = singleCommand->parsed() ? singleOptions : fullOptions;
    try {
        if (!o.recordFile.empty()) checkWritable(o.recordFile);
        ResultsRecord out(argc, argv);
        if (singleCommand->parsed())
            single(o, singleSize, singleSamples, out);
        else
            full(o, f, out);
        if (!o.recordFile.empty()) out.write(o.recordFile);
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "lucent-bench-peer: error: %s\n", e.what());
        return 1;
    }
}
