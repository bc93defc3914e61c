// Hybrid benchmark (thesis 4.7.3 and Table I of the journal version): the
// multiple-scattering solve of --method lbl, and its accuracy against the path
// tracer.
//
//   build/bin/lucent-bench-hybrid speed    [--grids 64,128] [--albedos 0.5,0.9,0.99] [--repeats N]
//   build/bin/lucent-bench-hybrid mdom     [--grids 64,128] [--directions 24,48] [--iterations 3] [--albedo 0.9]
//                                          [--g 0.8] [--repeats N] [--moments 16]
//   build/bin/lucent-bench-hybrid accuracy [--grids 64,128] [--albedos 0.5,0.8,0.95] [--g G] [--spp N] [--size N]
//                                          [--method lbl|mdom] [--directions 24,48,120] [--moments 16]
//                                          [--models sphere,bunny] [--light X,Y,Z] [--ior 1]
//   build/bin/lucent-bench-hybrid refraction [--iors 1.33,1.5] [--spp N] [--size N] [--repeats N] [--frame-size N]
//                                            [--models sphere,bunny,bunny-back]
//   build/bin/lucent-bench-hybrid pool     [--grids 128,256] [--pools 0,25,5] [--directions 24] [--moments 9,16]
//                                          [--iterations 2] [--repeats N]
//   every subcommand also takes [--record docs/results/hybrid-SUBCOMMAND.md]
//
// speed: on the bundled sphere lit by one point light, the median over repeats of
// the whole solve, the lattice steps to convergence and the time per step, with
// marching and diffusion concurrent (thesis fig. 4.1) and in sequence, and the
// ray-history size k swept at the first grid and albedo.
// accuracy: relative RMSE of luminance of ss and of lbl or mdom against --method
// path on the sphere and the bunny (no surface term), for every grid and albedo
// (and, for mdom, every direction count); the path tracer renders twice, and its
// own noise, measured from the two, is taken out of the errors; --ior sets
// every object's index of refraction.
// refraction: on the sphere (sigma_t 2, albedo 0.75) and the wax bunny (sigma_t
// 8, albedo 0.95, one point light in front; bunny-back: behind) at each ior: ss against the refracting
// single-scattering reference (at pixel centres, and over pixel means), and
// ss, lbl and mdom against the path tracer (its noise taken out); and ss's
// frame drawn again with its light and view cached (in turn with the
// index-matched frame), and its whole render, at ior 1 and at that ior, the
// medians measured in the same run.
#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdio>

#include "bench/path_truth.h"
#include "bench/results_record.h"
#include "bench/ss_frame.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/image_compare.h"
#include "core/loaded_scene.h"
#include "core/statistics.h"
#include "core/stopwatch.h"
#include "hybrid/mdom_scattering.h"
#include "hybrid/multiple_scattering.h"
#include "hybrid/voxelisation.h"
#include "methods/method_table.h"
#include "preprocess/preprocessor.h"
#include "runtime/offscreen_context.h"
#include "runtime/offscreen_frame.h"
#include "runtime/opengl.h"
#include "runtime/scattering_renderer.h"

using namespace lucent;

namespace {

SceneDesc sceneOf(const std::string& model, double albedo, double g = 0.0) {
    SceneDesc s = parseScene(std::string(LUCENT_SOURCE_DIR) + "/models/" + model + ".json");
    for (ObjectDesc& o : s.objects) {
        o.medium.albedo = Rgb(albedo);
        o.medium.g = g;
    }
    s.objects.resize(1);
    return s;
}

void speed(ResultsRecord& out, const std::vector<int>& grids, const std::vector<double>& albedos,
           const std::vector<int>& ks, int repeats, int subSteps) {
    hybrid::MultipleScattering solver;
    out.addDevice("OpenCL: " + solver.deviceName());
    out.print("lbl's solve on the bundled sphere, one point light; the median of %d repeats\n\n", repeats);
    out.tableHeader({"grid", "albedo", "k", "mode", "lattice steps", "iterations", "solve (s)", "per lattice step (ms)",
                     "march (s)", "rays", "converged"},
                    {true, true, true, false, true, true, true, true, true, true, false});
    auto run = [&](int grid, double albedo, int k, bool concurrent) {
        const SceneDesc scene = sceneOf("sphere", albedo);
        std::vector<std::string> warnings;
        const VolumeObject object(scene.objects[0], warnings);
        hybrid::HybridSettings s;
        s.resolution = grid;
        s.marchSteps = k;
        s.concurrent = concurrent;
        s.subSteps = subSteps;
        std::vector<double> times, marchTimes;
        hybrid::HybridStats stats;
        // Untimed first: PoCL compiles each kernel for its launch shape on first use.
        solver.solve(object, scene.lights, s, &stats);
        for (int r = 0; r < repeats; ++r) {
            solver.solve(object, scene.lights, s, &stats);
            times.push_back(stats.solveSeconds);
            marchTimes.push_back(stats.marchSeconds);
        }
        const double t = median(times);
        // Marching alone is timed only when it does not overlap diffusion.
        const std::string march = concurrent ? "" : std::to_string(median(marchTimes)).substr(0, 5);
        out.print("| %d | %.2f | %d | %s | %d | %d | %.3f | %.2f | %s | %zu | %s |\n", grid, albedo, k,
                  concurrent ? "concurrent" : "sequential", stats.latticeSteps, stats.iterations, t,
                  1e3 * t / std::max(1, stats.latticeSteps), march.c_str(), stats.rays, stats.converged ? "yes" : "no");
    };
    for (int grid : grids)
        for (double albedo : albedos)
            for (bool concurrent : {true, false}) run(grid, albedo, 16, concurrent);
    for (int k : ks)
        if (k != 16) run(grids.front(), albedos.front(), k, true);
}

void accuracy(ResultsRecord& out, const std::vector<int>& grids, const std::vector<double>& albedos, int spp, int size,
              double g, const std::string& method, const std::vector<int>& directions, const std::vector<int>& moments,
              const std::vector<std::string>& models, const std::vector<double>& light, double ior) {
    out.print(
        "relative RMSE of luminance against --method path at %d paths per pixel (its own noise taken out), "
        "%dx%d, no surface term%s\n\n",
        spp, size, size, ior == 1.0 ? "" : (", every object at ior " + std::to_string(ior).substr(0, 4)).c_str());
    out.tableHeader({"model", "albedo", "g", "grid", "directions", "moments", "path noise", "ss", method,
                     method + " raw", method + " mean ratio", method + " (s)", "path (s)"},
                    {false, true, true, true, true, true, true, true, true, true, true, true, true});
    for (const std::string& model : models)
        for (double albedo : albedos) {
            SceneDesc scene = sceneOf(model.c_str(), albedo, g);
            if (light.size() == 3) scene.lights[0].position = Vec3(light[0], light[1], light[2]);
            for (ObjectDesc& o : scene.objects) o.medium.ior = ior;
            scene.camera.width = scene.camera.height = size;
            LoadedScene loaded = loadScene(scene, false);
            attachSamples(loaded, {preprocessObject(loaded.objects[0], qualityPreset("default"))});
            MethodSettings settings;
            settings.surface = false;
            const PathTruth truth = pathTruth(loaded, settings, spp);
            const Image &pathA = truth.a, &pathB = truth.b, &path = truth.mean;
            const double pathSeconds = truth.seconds;
            Stopwatch stopwatch;
            const Image ss = renderWith(findMethod("ss"), loaded, settings);
            const NoisyReferenceError ssError = luminanceRelativeRmse(ss, pathA, pathB);
            for (int grid : grids)
                for (int n : method == "mdom" ? directions : std::vector<int>{0})
                    for (int m : method == "mdom" ? moments : std::vector<int>{0}) {
                        const MethodEntry& entry = findMethod(method);
                        MethodOptions options(entry.options);
                        options.set("grid", grid);
                        if (n > 0) options.set("directions", n);
                        if (m > 0) options.set("moments", m);
                        stopwatch.restart();
                        const Image image = renderWith(entry, *entry.create(options), loaded, settings);
                        const double seconds = stopwatch.seconds();
                        const NoisyReferenceError e = luminanceRelativeRmse(image, pathA, pathB);
                        out.print(
                            "| %s | %.2f | %.2f | %d | %d | %d | %.4f | %.4f | %.4f | %.4f | %.3f | %.2f | %.1f |\n",
                            model.c_str(), albedo, g, grid, n, m, e.noise, ssError.debiased, e.debiased, e.raw,
                            meanLuminance(image) / meanLuminance(path), seconds, pathSeconds);
                    }
        }
}

// The scenes of issue 41: the bundled sphere, and the bunny as wax, lit by the
// bundled bunny's first light (front, above) or by its second alone
// (bunny-back: behind, at the side), where the light that reaches the eye
// has crossed the object.
SceneDesc refractionScene(const std::string& model, double ior) {
    SceneDesc s = sceneOf(model == "sphere" ? "sphere" : "bunny", model == "sphere" ? 0.75 : 0.95);
    if (model != "sphere") {
        s.objects[0].medium.sigmaT = Rgb(8.0);
        s.lights.erase(s.lights.begin() + (model == "bunny-back" ? 0 : 1));
    }
    s.objects[0].medium.ior = ior;
    return s;
}

// A picture's pixel is the mean over its area, not its centre's value. The
// light refracted through the wax bunny's interpolated normals focuses into
// caustics finer than a pixel, where the reference's one ray per pixel centre
// finds values several times its neighbours' (and ss's silhouettes are drawn at
// pixel centres too): both drawn at kPixelStrata times the size and averaged
// over each pixel's kPixelStrata^2 sub-pixels compare what an image shows.
constexpr int kPixelStrata = 2;

Image pixelMeans(const Image& fine, int k) {
    Image coarse(fine.width / k, fine.height / k);
    for (int y = 0; y < coarse.height; ++y)
        for (int x = 0; x < coarse.width; ++x) {
            glm::vec3 sum(0.0f);
            for (int j = 0; j < k; ++j)
                for (int i = 0; i < k; ++i) sum += fine.at(k * x + i, k * y + j);
            coarse.at(x, y) = sum / float(k * k);
        }
    return coarse;
}

// ss against the single-scattering reference over pixel means (kPixelStrata).
double ssAgainstSingleOverPixels(const SceneDesc& scene, const SampleSet& samples, const MethodSettings& settings) {
    SceneDesc fine = scene;
    fine.camera.width *= kPixelStrata;
    fine.camera.height *= kPixelStrata;
    LoadedScene loaded = loadScene(fine, false);
    attachSamples(loaded, {samples});
    const Image single = pixelMeans(renderWith(findMethod("reference"), loaded, settings), kPixelStrata);
    const Image ss = pixelMeans(renderWith(findMethod("ss"), loaded, settings), kPixelStrata);
    return luminanceRelativeRmse(ss, single);
}

double medianRenderSeconds(const LoadedScene& loaded, const MethodSettings& settings, int repeats) {
    std::vector<double> times;
    for (int r = 0; r < repeats; ++r) {
        Stopwatch stopwatch;
        renderWith(findMethod("ss"), loaded, settings);
        times.push_back(stopwatch.seconds());
    }
    return median(times);
}

void refraction(ResultsRecord& out, const std::vector<std::string>& models, const std::vector<double>& iors, int spp,
                int size, int repeats, int frameSize) {
    const int frames = 20;
    out.print(
        "relative RMSE of luminance, %dx%d, no surface term: ss against --method reference (single scattering, "
        "refracting), at each pixel's centre and over pixel means (both drawn at %dx%d and averaged over %dx%d "
        "sub-pixels), and ss, lbl and mdom (default options) against --method path at %d paths per pixel (its "
        "noise taken out); ss's frame at %dx%d drawn again with its light and view cached (ms, the median of %d, "
        "drawn in turn with the index-matched one), and its whole render at %dx%d (s, the median of %d, with the "
        "light's solve through the boundary), at ior 1 and at the ior\n\n",
        size, size, kPixelStrata * size, kPixelStrata * size, kPixelStrata, kPixelStrata, spp, frameSize, frameSize,
        frames, size, size, repeats);
    out.tableHeader(
        {"model", "ior", "path noise", "ss vs single", "ss vs single, pixel means", "ss", "lbl", "mdom",
         "lbl mean ratio", "ss frame at ior 1 (ms)", "ss frame (ms)", "frame ratio", "ss render at ior 1 (s)",
         "ss render (s)", "render ratio", "reference (s)", "path (s)"},
        {false, true, true, true, true, true, true, true, true, true, true, true, true, true, true, true, true});
    for (const std::string& model : models) {
        SceneDesc matched = refractionScene(model, 1.0);
        matched.camera.width = matched.camera.height = size;
        LoadedScene indexMatched = loadScene(matched, false);
        // The samples do not depend on the ior: one set serves every row.
        const SampleSet samples = preprocessObject(indexMatched.objects[0], qualityPreset("default"));
        attachSamples(indexMatched, {samples});
        MethodSettings settings;
        settings.surface = false;
        const double matchedSeconds = medianRenderSeconds(indexMatched, settings, repeats);
        for (double ior : iors) {
            SceneDesc scene = refractionScene(model, ior);
            scene.camera = matched.camera;
            LoadedScene loaded = loadScene(scene, false);
            attachSamples(loaded, {samples});
            const PathTruth truth = pathTruth(loaded, settings, spp);
            const Image &pathA = truth.a, &pathB = truth.b, &path = truth.mean;
            Stopwatch stopwatch;
            const Image single = renderWith(findMethod("reference"), loaded, settings);
            const double referenceSeconds = stopwatch.seconds();
            const Image ss = renderWith(findMethod("ss"), loaded, settings);
            const double ssSeconds = medianRenderSeconds(loaded, settings, repeats);
            const auto [matchedFrameMs, frameMs] = ssFrameMsInTurn(indexMatched, loaded, frameSize, frames);
            const Image lbl = renderWith(findMethod("lbl"), loaded, settings);
            const Image mdom = renderWith(findMethod("mdom"), loaded, settings);
            const NoisyReferenceError lblError = luminanceRelativeRmse(lbl, pathA, pathB);
            out.print(
                "| %s | %.2f | %.4f | %.4f | %.4f | %.4f | %.4f | %.4f | %.3f | %.1f | %.1f | %.2f | %.2f | %.2f | "
                "%.2f | %.1f | %.1f |\n",
                model.c_str(), ior, lblError.noise, luminanceRelativeRmse(ss, single),
                ssAgainstSingleOverPixels(scene, samples, settings), luminanceRelativeRmse(ss, pathA, pathB).debiased,
                lblError.debiased, luminanceRelativeRmse(mdom, pathA, pathB).debiased,
                meanLuminance(lbl) / meanLuminance(path), matchedFrameMs, frameMs, frameMs / matchedFrameMs,
                matchedSeconds, ssSeconds, ssSeconds / matchedSeconds, referenceSeconds, truth.seconds);
        }
    }
}

hybrid::MdomSettings mdomSettings(int grid, int directions, int moments) {
    hybrid::MdomSettings s;
    s.resolution = grid;
    s.directions = directions;
    s.bands = int(std::lround(std::sqrt(double(moments))));
    return s;
}

// Thesis Table 5.1: the sphere lit by a point light, N directions, a fixed
// number of scattering iterations; time per iteration and per octant sweep,
// device memory, and after each iteration the share of the converged light
// still missing (the converged solve runs first, untimed, and compiles the kernels).
void mdomSpeed(ResultsRecord& out, const std::vector<int>& grids, const std::vector<int>& directions, int iterations,
               double albedo, double g, int repeats, int moments) {
    hybrid::MdomScattering solver;
    out.addDevice("OpenCL: " + solver.deviceName());
    out.print("mdom on the bundled sphere, albedo %.2f, g %.2f, one point light; the median of %d repeats\n\n", albedo,
              g, repeats);
    out.tableHeader({"grid", "directions", "moments", "iterations", "solve (s)", "per iteration (s)", "per sweep (s)",
                     "direct (s)", "memory (MiB)", "missing after each iteration"},
                    {true, true, true, true, true, true, true, true, true, false});
    const SceneDesc scene = sceneOf("sphere", albedo, g);
    std::vector<std::string> warnings;
    const VolumeObject object(scene.objects[0], warnings);
    const auto power = [](const hybrid::MdomSolution& s) {
        const int m = s.bands * s.bands;
        double sum = 0.0;
        for (size_t v = 0; v * m < s.moments.size(); ++v) sum += s.moments[v * m].g;
        return sum;
    };
    for (int grid : grids)
        for (int n : directions) {
            hybrid::MdomSettings s = mdomSettings(grid, n, moments);
            s.tolerance = 1e-4;
            const double converged = power(solver.solve(object, scene.lights, s));
            s.maxIterations = iterations;
            s.tolerance = 0.0;  // exactly `iterations`
            std::vector<double> times, directs;
            std::string missing;
            hybrid::MdomStats stats;
            for (int r = 0; r < repeats; ++r) {
                missing.clear();
                solver.solve(object, scene.lights, s, &stats, [&](int, const hybrid::MdomSolution& partial) {
                    missing +=
                        (missing.empty() ? "" : " ") + std::to_string(1.0 - power(partial) / converged).substr(0, 6);
                });
                times.push_back(stats.sweepSeconds);
                directs.push_back(stats.directSeconds);
            }
            const double t = median(times);
            const hybrid::GridShape shape = hybrid::gridShapeFor(object.mesh().bounds(), grid);
            const size_t bytes = hybrid::MdomScattering::bytesFor(shape.dims, n, s.bands);
            out.print("| %d | %d | %d | %d | %.2f | %.2f | %.3f | %.2f | %zu | %s |\n", grid, n, s.bands * s.bands,
                      iterations, t, t / iterations, t / (8 * iterations), median(directs), bytes >> 20,
                      missing.c_str());
        }
}

// The device pool (thesis 5.2.2 and 5.3.4): the same solve with the sweeps'
// volumes all on the device (the reference of time and flux) and streamed in
// blocks of 32^3 through pools of a share of them; the time ratios are
// measured in this run, and the flux moments compared to the reference's.
void mdomPool(ResultsRecord& out, const std::vector<int>& grids, const std::vector<double>& pools, int directions,
              const std::vector<int>& momentCounts, int iterations, int repeats) {
    hybrid::MdomScattering solver;
    out.addDevice("OpenCL: " + solver.deviceName());
    out.print(
        "mdom on the bundled sphere, albedo 0.90, g 0.80, one point light, %d directions, %d iterations; the "
        "median of %d repeats. Copies: per iteration, to the device and back. A pool that would hold every "
        "block is the whole grid.\n\n",
        directions, iterations, repeats);
    out.tableHeader(
        {"grid", "moments", "pool", "blocks held", "sweeps per iteration (s)", "against the whole grid",
         "copied up (GB)", "copied back (GB)", "device memory (MiB)", "host blocks (MiB)", "largest difference"},
        {true, true, false, false, true, true, true, true, true, true, true});
    const SceneDesc scene = sceneOf("sphere", 0.9, 0.8);
    std::vector<std::string> warnings;
    const VolumeObject object(scene.objects[0], warnings);
    for (int grid : grids)
        for (int moments : momentCounts) {
            hybrid::MdomSettings s = mdomSettings(grid, directions, moments);
            s.maxIterations = iterations;
            s.tolerance = 0.0;  // exactly `iterations`
            const hybrid::GridShape shape = hybrid::gridShapeFor(object.mesh().bounds(), grid);
            std::vector<glm::vec4> reference;  // the whole grid's flux
            double referenceTime = 0.0;
            for (double pool : pools) {
                s.devicePool = pool / 100.0;
                const std::string name = pool > 0.0 ? formatted("%g%%", pool) : "whole grid";
                std::vector<double> times;
                hybrid::MdomStats stats;
                std::vector<glm::vec4> flux;
                try {
                    for (int r = 0; r < repeats; ++r) {
                        flux = solver.solve(object, scene.lights, s, &stats).moments;
                        times.push_back(stats.sweepSeconds / iterations);
                    }
                } catch (const Error& e) {
                    out.print("| %d | %d | %s | | refused: %s | | | | | | |\n", grid, moments, name.c_str(), e.what());
                    continue;
                }
                const double t = median(times);
                double difference = 0.0, largest = 0.0;
                if (pool == 0.0) {
                    reference = std::move(flux);
                    referenceTime = t;
                } else if (!reference.empty()) {
                    for (size_t i = 0; i < flux.size(); ++i) {
                        largest = std::max(largest, double(std::abs(reference[i].g)));
                        difference = std::max(difference, double(std::abs(flux[i].g - reference[i].g)));
                    }
                }
                const size_t device = hybrid::MdomScattering::bytesFor(shape.dims, directions, s.bands, s.devicePool);
                const size_t host = hybrid::MdomScattering::poolHostBytes(shape.dims, s.bands, s.devicePool,
                                                                          object.desc().medium.ior != 1.0);
                out.print("| %d | %d | %s | %d of %d%s | %.2f | %s | %.2f | %.2f | %zu | %zu | %s |\n", grid, moments,
                          name.c_str(), stats.poolSlots, stats.poolBlocks, stats.spilled ? ", spilled to a file" : "",
                          t, referenceTime > 0.0 ? formatted("%.2f", t / referenceTime).c_str() : "",
                          stats.bytesToDevice / iterations / 1e9, stats.bytesFromDevice / iterations / 1e9,
                          device >> 20, host >> 20,
                          largest > 0.0 ? formatted("%.1e", difference / largest).c_str() : "");
            }
        }
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"Lucent hybrid benchmark: the lbl solve's speed, and its accuracy against the path tracer"};
    app.require_subcommand(1);
    std::vector<int> grids{64, 128}, ks{2, 4, 8, 16, 32, 64};
    std::vector<double> albedos;
    double g = 0.0;
    int repeats = 3, spp = 1024, size = 128, subSteps = hybrid::HybridSettings().subSteps;
    auto* sp = app.add_subcommand("speed", "Solve times, lattice steps, concurrent against sequential, k swept");
    sp->add_option("--grids", grids)->delimiter(',');
    sp->add_option("--albedos", albedos)->delimiter(',');
    sp->add_option("--ks", ks, "Ray-history sizes swept")->delimiter(',');
    sp->add_option("--repeats", repeats)->check(CLI::Range(1, 100));
    sp->add_option("--sub-steps", subSteps, "Lattice steps per block launch")->check(CLI::Range(1, 64));
    std::string method = "lbl";
    std::vector<int> directions{24, 48, 120}, moments{16};
    std::vector<std::string> models{"sphere", "bunny"};
    auto* ac = app.add_subcommand("accuracy", "Relative RMSE of ss and lbl or mdom against --method path");
    ac->add_option("--method", method, "The multiple-scattering method measured")
        ->check(CLI::IsMember({"lbl", "mdom"}));
    ac->add_option("--directions", directions, "mdom's propagation directions swept")->delimiter(',');
    ac->add_option("--moments", moments, "mdom's stored moments swept (4, 9, 16, 25, 36)")->delimiter(',');
    std::vector<double> light;
    ac->add_option("--light", light, "Position of the scene's first light, X,Y,Z")->delimiter(',')->expected(3);
    ac->add_option("--models", models, "Bundled models")->delimiter(',')->check(CLI::IsMember({"sphere", "bunny"}));
    ac->add_option("--grids", grids)->delimiter(',');
    ac->add_option("--albedos", albedos)->delimiter(',');
    ac->add_option("--spp", spp, "Paths per pixel of the ground truth")->check(CLI::Range(1, 1 << 20));
    ac->add_option("--size", size, "Image width and height")->check(CLI::Range(8, 2048));
    ac->add_option("--g", g, "Henyey-Greenstein g of the media")->check(CLI::Range(-0.99, 0.99));
    double ior = 1.0;
    ac->add_option("--ior", ior, "Index of refraction of the media")->check(CLI::Range(1.0, 4.0));
    int iterations = 3;
    double mdomAlbedo = 0.9, mdomG = 0.8;
    std::vector<int> mdomGrids{64, 128}, mdomDirections{24, 48};
    auto* md = app.add_subcommand("mdom", "Thesis Table 5.1: mdom's time per iteration and sweep, memory, convergence");
    md->add_option("--grids", mdomGrids)->delimiter(',');
    md->add_option("--directions", mdomDirections)->delimiter(',');
    md->add_option("--iterations", iterations)->check(CLI::Range(1, 100));
    md->add_option("--albedo", mdomAlbedo)->check(CLI::Range(0.0, 1.0));
    md->add_option("--g", mdomG)->check(CLI::Range(-0.99, 0.99));
    md->add_option("--repeats", repeats)->check(CLI::Range(1, 100));
    int mdomMoments = 16;
    md->add_option("--moments", mdomMoments, "Stored moments (4, 9, 16, 25, 36); fewer fit larger grids")
        ->check(CLI::IsMember({4, 9, 16, 25, 36}));
    std::vector<double> iors{1.33, 1.5};
    int refractionRepeats = 3, refractionSpp = 1024, refractionSize = 64, refractionFrame = 256;
    std::vector<int> poolGrids{128};
    std::vector<double> pools{0, 25, 5};
    std::vector<int> poolMoments{16};
    int poolDirections = 24, poolIterations = 2, poolRepeats = 1;
    auto* pl = app.add_subcommand("pool", "mdom's volumes streamed through a device pool: overhead and copies");
    pl->add_option("--grids", poolGrids)->delimiter(',');
    pl->add_option("--pools", pools, "Percent of the blocks the device holds; 0: the whole grid, unblocked")
        ->delimiter(',')
        ->check(CLI::Range(0.0, 100.0));
    pl->add_option("--directions", poolDirections)->check(CLI::IsMember({24, 48, 80, 120, 168}));
    pl->add_option("--moments", poolMoments)->delimiter(',')->check(CLI::IsMember({4, 9, 16, 25, 36}));
    pl->add_option("--iterations", poolIterations)->check(CLI::Range(1, 100));
    pl->add_option("--repeats", poolRepeats)->check(CLI::Range(1, 100));
    auto* rf = app.add_subcommand("refraction", "ss, lbl and mdom at refracting boundaries: accuracy and ss's time");
    rf->add_option("--iors", iors, "Indices of refraction")->delimiter(',')->check(CLI::Range(1.0, 4.0));
    rf->add_option("--spp", refractionSpp, "Paths per pixel of the ground truth")->check(CLI::Range(1, 1 << 20));
    rf->add_option("--size", refractionSize, "Image width and height")->check(CLI::Range(8, 2048));
    rf->add_option("--frame-size", refractionFrame, "Width and height of the timed ss frames")
        ->check(CLI::Range(8, 2048));
    rf->add_option("--repeats", refractionRepeats, "ss renders timed per row")->check(CLI::Range(1, 100));
    std::vector<std::string> refractionModels{"sphere", "bunny"};
    rf->add_option("--models", refractionModels,
                   "sphere, bunny (wax, lit from the front), bunny-back (lit from behind)")
        ->delimiter(',')
        ->check(CLI::IsMember({"sphere", "bunny", "bunny-back"}));
    std::string recordFile;
    for (CLI::App* sub : {sp, ac, md, rf, pl})
        sub->add_option("--record", recordFile, "Also write the results to this Markdown file (docs/results/)");
    CLI11_PARSE(app, argc, argv);
    try {
        if (!recordFile.empty()) checkWritable(recordFile);
        ResultsRecord out(argc, argv);
        if (pl->parsed())
            mdomPool(out, poolGrids, pools, poolDirections, poolMoments, poolIterations, poolRepeats);
        else if (rf->parsed())
            refraction(out, refractionModels, iors, refractionSpp, refractionSize, refractionRepeats, refractionFrame);
        else if (md->parsed())
            mdomSpeed(out, mdomGrids, mdomDirections, iterations, mdomAlbedo, mdomG, repeats, mdomMoments);
        else if (sp->parsed())
            speed(out, grids, albedos.empty() ? std::vector<double>{0.5, 0.9, 0.99} : albedos, ks, repeats, subSteps);
        else
            accuracy(out, grids, albedos.empty() ? std::vector<double>{0.5, 0.8, 0.95} : albedos, spp, size, g, method,
                     directions, moments, models, light, ior);
        if (!recordFile.empty()) out.write(recordFile);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "lucent-bench-hybrid: error: %s\n", e.what());
        return 1;
    }
    return 0;
}
