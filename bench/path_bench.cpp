// The path tracer's noise at equal time (issue 41: the ground truth gets
// faster where it is slowest): --method path on the index-matched wax bunny
// (the bundled bunny, sigma_t 8, albedo 0.95, one point light) and on the same
// bunny at ior 1.5, with each pixel's paths stratified in their first free
// flights (PathSampler) and independent. Per row: the per-pixel relative noise
// of one render (from two renders with independent seeds: RMS of their
// difference over sqrt 2, over the mean, where the mean is lit), the render's
// time (the median of the repeats), and the time one render needs to reach
// 5% noise, which scales as noise^2.
//
//   build/bin/lucent-bench-path [--size 64] [--spp 64,256] [--iors 1,1.5] [--repeats 3]
//                               [--record docs/results/path.md]
#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdio>

#include "bench/results_record.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/loaded_scene.h"
#include "core/statistics.h"
#include "core/stopwatch.h"
#include "reference/path_tracer.h"

namespace lucent {
namespace {

SceneDesc waxBunny(double ior, int size) {
    SceneDesc s = parseScene(std::string(LUCENT_SOURCE_DIR) + "/models/bunny.json");
    s.objects.resize(1);
    s.objects[0].medium.sigmaT = Rgb(8.0);
    s.objects[0].medium.albedo = Rgb(0.95);
    s.objects[0].medium.ior = ior;
    s.lights.resize(1);
    s.render.surface = false;
    s.camera.width = s.camera.height = size;
    return s;
}

double luminanceOf(const glm::vec3& c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }

// Relative noise of one render: the two renders' difference, per pixel, where their mean is lit.
double relativeNoise(const Image& a, const Image& b) {
    double mean = 0.0, squares = 0.0, peak = 0.0;
    std::vector<double> la(a.pixels.size()), lb(b.pixels.size());
    for (size_t i = 0; i < la.size(); ++i) {
        la[i] = luminanceOf(a.pixels[i]);
        lb[i] = luminanceOf(b.pixels[i]);
        peak = std::max(peak, 0.5 * (la[i] + lb[i]));
    }
    size_t lit = 0;
    for (size_t i = 0; i < la.size(); ++i) {
        if (0.5 * (la[i] + lb[i]) <= 1e-3 * peak) continue;
        mean += 0.5 * (la[i] + lb[i]);
        squares += (la[i] - lb[i]) * (la[i] - lb[i]);
        ++lit;
    }
    if (lit == 0) throw Error("lucent-bench-path: the image is black");
    return std::sqrt(squares / (2.0 * double(lit))) / (mean / double(lit));
}

void run(ResultsRecord& out, int size, const std::vector<int>& spps, const std::vector<double>& iors, int repeats) {
    out.print(
        "--method path on the wax bunny (sigma_t 8, albedo 0.95, one point light), %dx%d, no surface term; noise "
        "per pixel of one render, its time (the median of %d), and the time to 5%% noise (time x (noise / 0.05)^2)\n\n",
        size, size, repeats);
    out.tableHeader(
        {"ior", "paths per pixel", "paths", "noise", "time (s)", "to 5% (s)", "stratified over independent"},
        {true, true, false, true, true, true, true});
    for (double ior : iors) {
        const SceneDesc scene = waxBunny(ior, size);
        std::vector<std::string> warnings;
        const std::vector<VolumeObject> objects = loadObjects(scene, warnings);
        const PathTracer tracer(scene, objects);
        for (int spp : spps) {
            double toFive[2] = {0.0, 0.0};
            for (bool stratified : {false, true}) {
                PathSettings settings;
                settings.samplesPerPixel = spp;
                settings.surface = false;
                settings.stratified = stratified;
                std::vector<double> times;
                Image images[2];
                for (int r = 0; r < std::max(repeats, 2); ++r) {
                    settings.seed = uint64_t(r % 2 + 1);
                    const Stopwatch stopwatch;
                    Image image = tracer.render(settings).mean;
                    times.push_back(stopwatch.seconds());
                    if (r < 2) images[r] = std::move(image);
                }
                const double noise = relativeNoise(images[0], images[1]), seconds = median(times);
                toFive[stratified] = seconds * (noise / 0.05) * (noise / 0.05);
                out.print("| %.2f | %d | %s | %.4f | %.2f | %.2f | %s |\n", ior, spp,
                          stratified ? "stratified" : "independent", noise, seconds, toFive[stratified],
                          stratified ? (std::to_string(toFive[1] / toFive[0]).substr(0, 4) + "x").c_str() : "");
            }
        }
    }
}

}  // namespace
}  // namespace lucent

int main(int argc, char** argv) {
    using namespace lucent;
    CLI::App app{"lucent-bench-path: the path tracer's noise at equal time, stratified and independent"};
    int size = 64, repeats = 3;
    std::vector<int> spps{64, 256};
    std::vector<double> iors{1.0, 1.5};
    std::string recordFile;
    app.add_option("--size", size, "Image width and height")->check(CLI::Range(8, 2048));
    app.add_option("--spp", spps, "Paths per pixel")->delimiter(',')->check(CLI::Range(1, 1 << 20));
    app.add_option("--iors", iors, "Indices of refraction")->delimiter(',')->check(CLI::Range(1.0, 4.0));
    app.add_option("--repeats", repeats, "Renders timed per row (at least 2: the noise needs two seeds)")
        ->check(CLI::Range(2, 100));
    app.add_option("--record", recordFile, "Also write the results to this Markdown file (docs/results/)");
    CLI11_PARSE(app, argc, argv);
    try {
        if (!recordFile.empty()) checkWritable(recordFile);
        ResultsRecord out(argc, argv);
        run(out, size, spps, iors, repeats);
        if (!recordFile.empty()) out.write(recordFile);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "lucent-bench-path: error: %s\n", e.what());
        return 1;
    }
    return 0;
}
