// The peer benchmark: --method ss beside Blender's Cycles, the production path
// tracer a user of this machine would pick instead, on the bunny's single
// scattering (sigma_t 8, albedo 0.95, one point light, 256x256, seen from 5
// units). Both are measured against --method reference (exact single
// scattering): relative RMSE 2 px inside the silhouette, and render time
// (ss: the median frame after warm-up, preprocessing apart; Cycles: its render
// call, Blender's start and scene set-up apart, bench/cycles/render_scene.py).
// Then, at ss's error, how many samples Cycles needs and how long it takes.
//
//   build/bin/lucent-bench-peer [SCENE] [--size 256] [--distance 5] [--samples 1,2,4,...]
//                               [--frames 15] [--warmup 3] [--blender blender] [--out DIR]
//
// Cycles comes from Debian's `blender` (scripts/install-bench-deps.sh); the
// tests never need it.
#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdio>
#include <fstream>

#include "bench/results_record.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/image_compare.h"
#include "core/loaded_scene.h"
#include "core/scene.h"
#include "core/run_program.h"
#include "core/stopwatch.h"
#include "core/volume_object.h"
#include "preprocess/preprocessor.h"
#include "reference/reference_renderer.h"
#include "runtime/offscreen_context.h"
#include "runtime/offscreen_frame.h"
#include "runtime/scattering_renderer.h"

using namespace lucent;

namespace {

// The scene: the default scene's first object and first light, grey
// sigma_t 8 and albedo 0.95, the camera moved to `distance` along its own
// direction with a field of view that frames the object, no surface term.
SceneDesc peerScene(const std::string& file, int size, double distance) {
    SceneDesc s = parseScene(file);
    s.objects.resize(1);
    s.lights.resize(1);
    s.objects[0].medium.sigmaT = Rgb(8.0);
    s.objects[0].medium.albedo = Rgb(0.95);
    s.objects[0].medium.g = 0.0;
    const double grey = (s.lights[0].power.r + s.lights[0].power.g + s.lights[0].power.b) / 3.0;
    s.lights[0].power = Rgb(grey);
    Camera& c = s.camera;
    c.position = c.target + distance * glm::normalize(c.position - c.target);
    c.width = c.height = size;
    return s;
}

void writeObj(const std::filesystem::path& file, const TriangleMesh& mesh) {
    std::ofstream out(file);
    out.precision(9);
    for (const Vec3& p : mesh.positions) out << "v " << p.x << ' ' << p.y << ' ' << p.z << '\n';
    for (const auto& t : mesh.triangles) out << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
    if (!out) throw Error(file.string(), "cannot write");
}

std::string json3(const Vec3& v) {
    char b[160];
    std::snprintf(b, sizeof b, "[%.9g, %.9g, %.9g]", v.x, v.y, v.z);
    return b;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"Lucent peer benchmark: ss beside Blender's Cycles at equal error"};
    std::string sceneFile = std::string(LUCENT_SOURCE_DIR) + "/models/bunny.json";
    int size = 256, frames = 15, warmup = 3;
    double distance = 5.0;
    std::vector<int> samples{1, 2, 4, 8, 16, 32, 64, 128, 256};
    std::string blender = "blender", outDir = "peer-bench";
    app.add_option("scene", sceneFile, "Scene whose first object and light are rendered");
    app.add_option("--size", size, "Image width and height")->check(CLI::Range(8, 4096));
    app.add_option("--distance", distance, "Camera distance from its target")->check(CLI::Range(1e-3, 1e6));
    app.add_option("--samples", samples, "Cycles' samples per pixel swept")
        ->delimiter(',')
        ->check(CLI::Range(1, 1 << 20));
    app.add_option("--frames", frames, "ss: timed frames (median reported)")->check(CLI::Range(1, 10000));
    app.add_option("--warmup", warmup, "ss: untimed frames first")->check(CLI::Range(0, 10000));
    app.add_option("--blender", blender, "The Blender program (Debian's blender package)");
    app.add_option("--out", outDir, "Directory for the images and Cycles' scene");
    std::string recordFile;
    app.add_option("--record", recordFile, "Also write the results to this Markdown file (docs/results/)");
    CLI11_PARSE(app, argc, argv);
    try {
        if (!recordFile.empty()) checkWritable(recordFile);
        ResultsRecord out(argc, argv);
        SceneDesc scene = peerScene(sceneFile, size, distance);
        std::vector<std::string> warnings;
        const std::vector<VolumeObject> objects = loadObjects(scene, warnings);
        const VolumeObject& object = objects.front();
        // Frame the object: its bounding sphere fills 90% of the height.
        const Bounds3 bounds = object.mesh().bounds();
        scene.camera.target = bounds.center();
        const double radius = 0.5 * bounds.diagonal();
        scene.camera.fovYDegrees = 2.0 * std::asin(std::min(1.0, radius / distance)) * 180.0 / kPi / 0.9;
        std::filesystem::create_directories(outDir);
        const std::filesystem::path dir = std::filesystem::absolute(outDir);

        Stopwatch stopwatch;
        const SampleSet sampleSet = checkSamplesBelong(object, preprocessObject(object, qualityPreset("default")),
                                                       "in-memory samples of " + object.desc().name);
        const double preprocessSeconds = stopwatch.seconds();

        stopwatch.restart();
        ReferenceSettings rs;
        rs.surface = false;
        const Image reference = ReferenceRenderer(scene, objects).render(rs);
        const double referenceSeconds = stopwatch.seconds();
        writeImage(dir / "reference.pfm", reference);

        // ss: frames after warm-up on this machine's OpenGL.
        const auto context = OffscreenContext::create(GlBackend::Auto);
        out.addDevice(std::string(context->backendName()) + ": " + glRenderer());
        OffscreenFrame frame(size, size);
        ScatteringRenderer renderer;
        renderer.addObject(translucentObjectFor(object, sampleSet));
        renderer.setLights(scene.lights);
        const ViewSetup view = viewSetupFor(scene.camera, bounds);
        DrawOptions options;
        options.surface = false;
        const double ssSeconds = medianFrameSeconds(
            warmup, frames, [&] { frame.bindAndClear(); }, [&] { renderer.draw(view, options); });
        const Image ss = frame.read();
        writeImage(dir / "ss.pfm", ss);
        const double ssError = compareImages(ss, reference, 2).relativeRmse;

        // Cycles, in one Blender process for every sample count.
        writeObj(dir / "mesh.obj", object.mesh());
        const MediumDesc& m = object.desc().medium;
        const Rgb sigmaS = m.sigmaT * m.albedo, sigmaA = m.sigmaT - sigmaS;
        std::string list;
        for (int n : samples) list += (list.empty() ? "" : ", ") + std::to_string(n);
        {
            std::ofstream spec(dir / "peer-scene.json");
            spec << "{\"mesh\": \"" << (dir / "mesh.obj").string() << "\",\n"
                 << " \"camera\": {\"position\": " << json3(scene.camera.position)
                 << ", \"target\": " << json3(scene.camera.target) << ", \"up\": " << json3(scene.camera.up)
                 << ", \"fov_y\": " << scene.camera.fovYDegrees << ", \"width\": " << size << ", \"height\": " << size
                 << "},\n \"lights\": [{\"position\": " << json3(scene.lights[0].position)
                 << ", \"intensity\": " << json3(Vec3(scene.lights[0].power)) << "}],\n"
                 << " \"medium\": {\"sigma_s\": " << json3(Vec3(sigmaS)) << ", \"sigma_a\": " << json3(Vec3(sigmaA))
                 << ", \"g\": " << m.g << "},\n \"samples\": [" << list
                 << "], \"seed\": 1, \"threads\": 2, \"output\": \"" << dir.string() << "\"}\n";
            if (!spec) throw Error((dir / "peer-scene.json").string(), "cannot write");
        }
        const std::filesystem::path script = std::filesystem::path(LUCENT_SOURCE_DIR) / "bench/cycles/render_scene.py";
        const std::filesystem::path log = dir / "blender.log";
        std::fprintf(stderr, "running Cycles (%s) for %zu sample counts, its output in %s...\n", blender.c_str(),
                     samples.size(), log.c_str());
        const int status = runProgram({blender, "-b", "--factory-startup", "-noaudio", "--python-exit-code", "1",
                                       "--python", script.string(), "--", (dir / "peer-scene.json").string()},
                                      log);
        if (status != 0)
            throw Error(blender,
                        "Cycles' render failed (exit " + std::to_string(status) + "; see " + log.string() + ")");

        out.print(
            "scene %s's first object and light, sigma_t 8, albedo 0.95, %dx%d, camera %.2f away; "
            "error: relative RMSE 2 px inside the silhouette against --method reference (%.2f s)\n\n",
            std::filesystem::path(sceneFile).filename().c_str(), size, size, distance, referenceSeconds);
        out.tableHeader({"renderer", "setting", "error", "render time (s)"}, {false, false, true, true});
        out.print("| ss | default quality (preprocessing %.1f s apart), median of %d frames | %.2f%% | %.4f |\n",
                  preprocessSeconds, frames, 100.0 * ssError, ssSeconds);
        std::ifstream timesFile(dir / "cycles-times.csv");
        std::string line;
        std::getline(timesFile, line);  // header
        int equalSamples = 0;
        double equalSeconds = 0.0;
        while (std::getline(timesFile, line)) {
            int n = 0;
            double seconds = 0.0;
            if (std::sscanf(line.c_str(), "%d,%lf", &n, &seconds) != 2)
                throw Error("cycles-times.csv", "bad line: " + line);
            const Image cycles = readPfm(dir / ("cycles-" + std::to_string(n) + ".pfm"));
            const ImageError e = compareImages(cycles, reference, 2);
            out.print("| Cycles | %d samples per pixel | %.2f%% (mean ratio %.3f) | %.4f |\n", n,
                      100.0 * e.relativeRmse, e.meanRatio, seconds);
            if (!equalSamples && e.relativeRmse <= ssError) {
                equalSamples = n;
                equalSeconds = seconds;
            }
        }
        if (equalSamples)
            out.print(
                "\nAt ss's error (%.2f%%), Cycles needs %d samples per pixel: %.4f s against ss's %.4f s (%.1fx).\n",
                100.0 * ssError, equalSamples, equalSeconds, ssSeconds, equalSeconds / ssSeconds);
        else
            out.print("\nNo sample count swept brings Cycles to ss's error (%.2f%%).\n", 100.0 * ssError);
        if (!recordFile.empty()) out.write(recordFile);
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "lucent-bench-peer: error: %s\n", e.what());
        return 1;
    }
}
