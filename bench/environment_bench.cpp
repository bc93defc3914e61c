// Environment benchmark (issue 42): what an environment light costs each method
// against the scene's point light, and how close each method draws it to the
// path tracer. The environment is a sky with a sun, made here: a blue sky above
// the horizon, a dim ground below, and a sun of 2 x 2 texels from where the
// scene's point light stands, giving the object's centre the point light's
// irradiance there (the sky adds a tenth of it again).
//
//   build/bin/lucent-bench-environment [--models sphere,bunny] [--size N] [--spp N] [--repeats N]
//                                      [--frame-size N] [--record docs/results/environment.md]
//
// Per model and light: ss against --method reference (single scattering), ss,
// lbl and mdom against --method path (rendered twice, its noise taken out),
// every method's whole render (the median of the repeats), and ss's frame drawn
// again with the light cached (the viewer's frame), all with default options.
// Then, under the sky, the counts of directional lights the environment becomes:
// ss's --env-lights against the reference, and the lights lbl's and mdom's grids
// are solved for (kGridEnvironmentLights) against the path tracer. Last, ss
// --light sh: the environment projected onto SH against the point light.
#include <CLI/CLI.hpp>

#include <cmath>
#include <map>
#include <cstdio>

#include "bench/path_truth.h"
#include "bench/results_record.h"
#include "bench/ss_frame.h"
#include "core/atomic_file.h"
#include "core/environment_map.h"
#include "core/error.h"
#include "core/image_compare.h"
#include "core/loaded_scene.h"
#include "core/statistics.h"
#include "core/stopwatch.h"
#include "hybrid/mdom_scattering.h"
#include "hybrid/multiple_scattering.h"
#include "methods/grid_method.h"
#include "methods/method_table.h"
#include "preprocess/preprocessor.h"
#include "runtime/offscreen_context.h"
#include "runtime/offscreen_frame.h"
#include "runtime/opengl.h"
#include "runtime/scattering_renderer.h"
#include "runtime/ss_method.h"

using namespace lucent;

namespace {

// The sky with a sun from the direction toSun, the sun's irradiance E.
std::shared_ptr<const EnvironmentMap> skyWithSun(const Vec3& toSun, double E) {
    const int width = 128, height = 64;
    const double t = std::acos(std::clamp(toSun.y, -1.0, 1.0));
    double p = std::atan2(-toSun.z, toSun.x);
    if (p < 0.0) p += 2.0 * kPi;
    const int sx = std::clamp(int(p / (2.0 * kPi) * width), 0, width - 2);
    const int sy = std::clamp(int(t / kPi * height), 0, height - 2);
    double sunSolidAngle = 0.0;
    for (int y = sy; y < sy + 2; ++y)
        sunSolidAngle += 2.0 * 2.0 * kPi / width * (std::cos(kPi * y / height) - std::cos(kPi * (y + 1) / height));
    // A sky of uniform radiance over the upper hemisphere gives pi L on a face
    // looking up: a tenth of the sun's irradiance.
    const double sky = 0.1 * E / kPi;
    Image image(width, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            image.at(x, y) = y < height / 2 ? glm::vec3(glm::dvec3(0.6, 0.9, 1.6) * sky)
                                            : glm::vec3(glm::dvec3(0.3, 0.25, 0.2) * sky);
    for (int y = sy; y < sy + 2; ++y)
        for (int x = sx; x < sx + 2; ++x) image.at(x, y) = glm::vec3(float(E / sunSolidAngle));
    return std::make_shared<const EnvironmentMap>(image, 1.0, glm::dmat3(1.0));
}

// The median of repeats whole renders with these options (none: the method's defaults); image: the first.
double medianRenderSeconds(const std::string& method, const LoadedScene& loaded, const MethodSettings& settings,
                           int repeats, Image* image, const std::map<std::string, std::string>& values = {}) {
    const MethodEntry& entry = findMethod(method);
    MethodOptions options(entry.options);
    for (const auto& [name, value] : values) options.set(name, value);
    std::vector<double> times;
    for (int r = 0; r < repeats; ++r) {
        Stopwatch stopwatch;
        Image rendered = renderWith(entry, *entry.create(options), loaded, settings);
        times.push_back(stopwatch.seconds());
        if (r == 0 && image) *image = std::move(rendered);
    }
    return median(times);
}

struct Row {
    double ssSingle = 0, ss = 0, lbl = 0, mdom = 0, noise = 0;
    double ssSeconds = 0, lblSeconds = 0, mdomSeconds = 0, referenceSeconds = 0, pathSeconds = 0, frameMs = 0;
};

Row measure(const LoadedScene& loaded, int spp, int repeats, int frameSize) {
    MethodSettings settings;
    settings.surface = false;
    Row row;
    const PathTruth truth = pathTruth(loaded, settings, spp);
    row.pathSeconds = truth.seconds;
    Image reference, ss, lbl, mdom;
    row.referenceSeconds = medianRenderSeconds("reference", loaded, settings, 1, &reference);
    row.ssSeconds = medianRenderSeconds("ss", loaded, settings, repeats, &ss);
    row.lblSeconds = medianRenderSeconds("lbl", loaded, settings, repeats, &lbl);
    row.mdomSeconds = medianRenderSeconds("mdom", loaded, settings, repeats, &mdom);
    row.frameMs = ssFrameMs(loaded, frameSize, 20);
    row.ssSingle = luminanceRelativeRmse(ss, reference);
    const NoisyReferenceError lblError = luminanceRelativeRmse(lbl, truth.a, truth.b);
    row.noise = lblError.noise;
    row.lbl = lblError.debiased;
    row.ss = luminanceRelativeRmse(ss, truth.a, truth.b).debiased;
    row.mdom = luminanceRelativeRmse(mdom, truth.a, truth.b).debiased;
    return row;
}

// ss with count directional lights for the environment: its error against the
// reference and the median of its whole renders.
void ssCountRow(ResultsRecord& out, const std::string& model, const LoadedScene& sky, const Image& reference, int count,
                int repeats) {
    MethodSettings settings;
    settings.surface = false;
    Image image;
    const double seconds =
        medianRenderSeconds("ss", sky, settings, repeats, &image, {{"env-lights", std::to_string(count)}});
    out.print("| %s | ss | %d | %.4f | %.2f |\n", model.c_str(), count, luminanceRelativeRmse(image, reference),
              seconds);
}

// lbl's and mdom's grids solved for count of the environment's lights, drawn
// with ss's default: their error against the path tracer and the solve's time.
struct GridSolvers {
    hybrid::MultipleScattering lbl;
    hybrid::MdomScattering mdom;
};

void gridCountRows(ResultsRecord& out, GridSolvers& solvers, const std::string& model, const LoadedScene& sky,
                   const PathTruth& truth, int count) {
    MethodSettings settings;
    settings.surface = false;
    const std::vector<Light> lights = sky.lightsWithEnvironment(count);
    std::string backend;
    Stopwatch stopwatch;
    const std::vector<ScatteringGrid> lbl = {solvers.lbl.solve(sky.objects[0], lights, hybrid::HybridSettings{})};
    const double lblSeconds = stopwatch.seconds();
    stopwatch.restart();
    const std::vector<ScatteringGrid> mdom = {
        solvers.mdom.solve(sky.objects[0], lights, hybrid::MdomSettings{}).towards(sky.desc.camera.position)};
    const double mdomSeconds = stopwatch.seconds();
    for (const auto& [name, grids, seconds] : {std::tuple{"lbl", &lbl, lblSeconds}, {"mdom", &mdom, mdomSeconds}}) {
        const Image image = renderSingleScattering(sky, settings, SsOptions{}, *grids, backend);
        out.print("| %s | %s | %d | %.4f | %.2f |\n", model.c_str(), name, count,
                  luminanceRelativeRmse(image, truth.a, truth.b).debiased, seconds);
    }
}

struct SkyScene {
    std::string model;
    LoadedScene scene;
    Light point;  // the scene's point light, which the sky's sun stands in for
};

void environmentTable(ResultsRecord& out, const std::vector<std::string>& models, int size, int spp, int repeats,
                      int frameSize, std::vector<SkyScene>& counts) {
    out.print(
        "relative RMSE of luminance, %dx%d, no surface term, default options (--env-lights %d): ss against "
        "--method reference, and ss, lbl and mdom against --method path at %d paths per pixel (its noise taken "
        "out); whole renders in s (the median of %d; reference and path once), ss's frame at %dx%d in ms with the "
        "light cached (the median of 20)\n\n",
        size, size, SsOptions().environmentLights, spp, repeats, frameSize, frameSize);
    out.tableHeader({"model", "light", "path noise", "ss vs single", "ss", "lbl", "mdom", "ss (s)", "lbl (s)",
                     "mdom (s)", "reference (s)", "path (s)", "ss frame (ms)"},
                    {false, false, true, true, true, true, true, true, true, true, true, true, true});
    for (const std::string& model : models) {
        SceneDesc scene = parseScene(std::string(LUCENT_SOURCE_DIR) + "/models/" + model + ".json");
        scene.objects.resize(1);
        scene.lights.resize(1);
        scene.camera.width = scene.camera.height = size;
        LoadedScene lit = loadScene(scene, false);
        const SampleSet samples = preprocessObject(lit.objects[0], qualityPreset("default"));
        attachSamples(lit, {samples});
        const Light light = scene.lights[0];
        const Vec3 centre = lit.bounds().center();
        const double d = glm::length(light.position - centre);
        Row rows[2];
        rows[0] = measure(lit, spp, repeats, frameSize);
        lit.environment = skyWithSun((light.position - centre) / d, light.power.g / (d * d));
        lit.desc.lights.clear();
        rows[1] = measure(lit, spp, repeats, frameSize);
        for (int k = 0; k < 2; ++k) {
            const Row& r = rows[k];
            out.print("| %s | %s | %.4f | %.4f | %.4f | %.4f | %.4f | %.2f | %.2f | %.2f | %.1f | %.1f | %.1f |\n",
                      model.c_str(), k == 0 ? "point" : "sky with a sun", r.noise, r.ssSingle, r.ss, r.lbl, r.mdom,
                      r.ssSeconds, r.lblSeconds, r.mdomSeconds, r.referenceSeconds, r.pathSeconds, r.frameMs);
        }
        counts.push_back({model, std::move(lit), light});
        const Row &p = rows[0], &e = rows[1];
        out.print("| %s | environment / point | | | | | | %.2fx | %.2fx | %.2fx | %.2fx | %.2fx | %.2fx |\n",
                  model.c_str(), e.ssSeconds / p.ssSeconds, e.lblSeconds / p.lblSeconds, e.mdomSeconds / p.mdomSeconds,
                  e.referenceSeconds / p.referenceSeconds, e.pathSeconds / p.pathSeconds, e.frameMs / p.frameMs);
    }
}

void countsTable(ResultsRecord& out, std::vector<SkyScene>& skies, int spp, int repeats) {
    out.print(
        "\nunder the sky with a sun: ss with --env-lights N against --method reference (the median of %d whole "
        "renders); lbl and mdom (default options) with their grids solved for N of the environment's lights "
        "(the default: %d) and drawn with ss's default, against --method path at %d paths per pixel (its noise "
        "taken out), and the solve's time, once\n\n",
        repeats, kGridEnvironmentLights, spp);
    out.tableHeader({"model", "method", "N", "error", "time (s)"}, {false, false, true, true, true});
    MethodSettings settings;
    settings.surface = false;
    GridSolvers solvers;
    for (SkyScene& sky : skies) {
        // Untimed first: PoCL compiles each kernel for its launch shape on first use.
        const std::vector<Light> one = sky.scene.lightsWithEnvironment(1);
        solvers.lbl.solve(sky.scene.objects[0], one, hybrid::HybridSettings{});
        solvers.mdom.solve(sky.scene.objects[0], one, hybrid::MdomSettings{});
        const Image reference = renderWith(findMethod("reference"), sky.scene, settings);
        for (int count : {8, 16, 32, 64, 128}) ssCountRow(out, sky.model, sky.scene, reference, count, repeats);
        const PathTruth truth = pathTruth(sky.scene, settings, spp);
        for (int count : {4, 8, 16, 64}) gridCountRows(out, solvers, sky.model, sky.scene, truth, count);
    }
}

// One row of the --light sh table: ss's error against the reference, its whole render and its frame.
struct ShRow {
    double error = 0, seconds = 0, frameMs = 0;
};

ShRow shRow(const LoadedScene& scene, int repeats, int frameSize) {
    MethodSettings settings;
    settings.surface = false;
    const Image reference = renderWith(findMethod("reference"), scene, settings);
    Image image;
    const double seconds = medianRenderSeconds("ss", scene, settings, repeats, &image, {{"light", "sh"}});
    SsOptions sh;
    sh.tracedLight = false;
    return {luminanceRelativeRmse(image, reference), seconds, ssFrameMs(scene, frameSize, 20, sh)};
}

// ss --light sh: the sky projected onto SH per sample (ScatteringRenderer::setEnvironment)
// against the point light read from the SH, isotropic (the light cached) and at g = 0.5 (8 bands, each frame).
void shTable(ResultsRecord& out, std::vector<SkyScene>& skies, int repeats, int frameSize) {
    out.print(
        "\nss --light sh: the sky with a sun projected onto SH per sample (1 band at g = 0, 8 at g = 0.5) against "
        "the point light, each read from the samples' SH: error against --method reference, whole renders in s "
        "(the median of %d), the frame at %dx%d in ms (the median of 20; the light cached at g = 0 only)\n\n",
        repeats, frameSize, frameSize);
    out.tableHeader({"model", "g", "light", "error", "render (s)", "frame (ms)"},
                    {false, true, false, true, true, true});
    for (SkyScene& sky : skies) {
        for (double g : {0.0, 0.5}) {
            SceneDesc desc = sky.scene.desc;
            desc.objects[0].medium.g = g;
            LoadedScene lit = loadScene(desc, false);
            attachSamples(lit, {sky.scene.samples[0]});
            lit.environment = sky.scene.environment;
            ShRow rows[2];
            rows[1] = shRow(lit, repeats, frameSize);
            lit.environment.reset();
            lit.desc.lights = {sky.point};
            rows[0] = shRow(lit, repeats, frameSize);
            for (int k = 0; k < 2; ++k)
                out.print("| %s | %.1f | %s | %.4f | %.2f | %.1f |\n", sky.model.c_str(), g,
                          k == 0 ? "point" : "sky with a sun", rows[k].error, rows[k].seconds, rows[k].frameMs);
            out.print("| %s | %.1f | environment / point | | %.2fx | %.2fx |\n", sky.model.c_str(), g,
                      rows[1].seconds / rows[0].seconds, rows[1].frameMs / rows[0].frameMs);
        }
    }
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"Lucent environment benchmark: each method under a sky with a sun against one point light"};
    std::vector<std::string> models{"sphere", "bunny"};
    int size = 128, spp = 1024, repeats = 3, frameSize = 256;
    app.add_option("--models", models, "Bundled models")->delimiter(',')->check(CLI::IsMember({"sphere", "bunny"}));
    app.add_option("--size", size, "Image width and height")->check(CLI::Range(8, 2048));
    app.add_option("--spp", spp, "Paths per pixel of the ground truth")->check(CLI::Range(1, 1 << 20));
    app.add_option("--repeats", repeats, "Renders timed per method and row")->check(CLI::Range(1, 100));
    app.add_option("--frame-size", frameSize, "Width and height of the timed ss frames")->check(CLI::Range(8, 2048));
    std::string recordFile;
    app.add_option("--record", recordFile, "Also write the results to this Markdown file (docs/results/)");
    CLI11_PARSE(app, argc, argv);
    try {
        if (!recordFile.empty()) checkWritable(recordFile);
        ResultsRecord out(argc, argv);
        std::vector<SkyScene> skies;
        environmentTable(out, models, size, spp, repeats, frameSize, skies);
        countsTable(out, skies, spp, repeats);
        shTable(out, skies, repeats, frameSize);
        if (!recordFile.empty()) out.write(recordFile);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "lucent-bench-environment: error: %s\n", e.what());
        return 1;
    }
    return 0;
}
