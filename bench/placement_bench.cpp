// How far an object may be drawn from the optical size its samples were made
// for (issue 40: scale belongs to the optical regime). A bundled scene is
// placed at scale s0 and preprocessed there (the stale samples); it is then
// drawn at s = ratio s0 with those samples and with samples made at s (the
// fresh ones), each against --method reference at s. The camera and the point
// lights move and brighten with the scale, so that every image frames the same
// view: only the optical size changes. The error is the relative RMSE 2 px
// inside the silhouette; runtime/preprocessed_size.h takes its served ratio
// from this table.
//
//   build/bin/lucent-bench-placement [--size 128] [--record docs/results/placement.md]
#include <CLI/CLI.hpp>

#include <cstdio>

#include "bench/results_record.h"
#include "core/image_compare.h"
#include "core/loaded_scene.h"
#include "preprocess/preprocessor.h"
#include "reference/reference_renderer.h"
#include "runtime/ss_method.h"

using namespace lucent;

namespace {

struct Series {
    std::string scene;  // in models/
    double s0;
    std::vector<double> ratios;
};

// The scene with its object placed at scale s, seen and lit as at scale 1.
SceneDesc placedAt(const std::string& sceneName, double s, int size) {
    SceneDesc scene = parseScene(std::string(LUCENT_SOURCE_DIR) + "/models/" + sceneName + ".json");
    scene.objects.resize(1);
    scene.objects[0].transform.scale = s;
    scene.camera.position *= s;
    scene.camera.target *= s;
    scene.camera.width = scene.camera.height = size;
    for (Light& l : scene.lights) {
        if (l.type != Light::Type::Point) continue;
        l.position *= s;
        l.power *= s * s;
    }
    return scene;
}

SampleSet samplesAt(const SceneDesc& scene) {
    return preprocessObject(loadScene(scene, false).objects[0], qualityPreset("default"));
}

double errorOf(const SceneDesc& scene, const SampleSet& samples, const Image& truth) {
    LoadedScene loaded = loadScene(scene, false);
    attachSamples(loaded, {samples});
    MethodSettings settings;
    settings.surface = false;
    return compareImages(SsMethod(SsOptions{}).render(loaded, settings), truth, 2).relativeRmse;
}

std::string percent(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f%%", 100.0 * v);
    return text;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"ss with samples made at another optical size than the one drawn, against fresh samples"};
    int size = 128;
    std::string record;
    app.add_option("--size", size, "Image width and height")->check(CLI::Range(16, 1024));
    app.add_option("--record", record, "Also write the results to this Markdown file (docs/results/)");
    CLI11_PARSE(app, argc, argv);
    try {
        ResultsRecord out(argc, argv);
        out.print(
            "ss at scale s = ratio s0, default quality, %dx%d, relative RMSE 2 px inside the silhouette against "
            "--method reference at s: with the samples made at s0 (stale) and at s (fresh). The sphere (sigma_t 2, "
            "radius 1) and the bunny (sigma_t 6-12, about 1.2 across) from s0 = 1; the sphere from s0 = 32, where "
            "it is optically thick and has no samples.\n\n",
            size, size);
        out.tableHeader({"scene", "s0", "ratio s / s0", "stale", "fresh", "stale - fresh"},
                        {false, true, true, true, true, true});
        const std::vector<Series> series = {{"sphere", 1.0, {0.05, 0.25, 0.5, 2.0, 4.0, 8.0, 16.0}},
                                            {"bunny", 1.0, {0.1, 0.25, 0.5, 2.0, 4.0, 8.0}},
                                            {"sphere", 32.0, {0.125, 0.25, 0.5}}};
        for (const Series& s : series) {
            const SampleSet stale = samplesAt(placedAt(s.scene, s.s0, size));
            for (const double ratio : s.ratios) {
                const SceneDesc scene = placedAt(s.scene, s.s0 * ratio, size);
                std::fprintf(stderr, "lucent-bench-placement: %s at %g times %g\n", s.scene.c_str(), ratio, s.s0);
                ReferenceSettings reference;
                reference.surface = false;
                const LoadedScene loaded = loadScene(scene, false);
                const Image truth = ReferenceRenderer(scene, loaded.objects).render(reference);
                const double staleError = errorOf(scene, stale, truth);
                const double freshError = errorOf(scene, samplesAt(scene), truth);
                char ratioText[32], s0Text[32], gap[32];
                std::snprintf(ratioText, sizeof ratioText, "%g", ratio);
                std::snprintf(s0Text, sizeof s0Text, "%g", s.s0);
                std::snprintf(gap, sizeof gap, "%+.1f", 100.0 * (staleError - freshError));
                out.tableRow({s.scene, s0Text, ratioText, percent(staleError), percent(freshError), gap});
            }
        }
        if (!record.empty()) out.write(record);
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "lucent-bench-placement: %s\n", e.what());
        return 1;
    }
}
