// Preprocessing benchmark: the per-stage times of thesis Table 3.1 (optical depth
// for the heuristic, divergence, Poisson-disk sampling, SH projection) and rays
// cast per second, for several direction counts and the default preset, median
// of repeated runs. "SH projection" holds everything after the Poisson disks:
// describing the samples (closest points, mirror images, balls), their weights
// and the projection itself.
//
//   build/bin/lucent-bench-preprocess [SCENE] [--samples N] [--repeats R] [--directions 64,128,256]
//                                     [--record docs/results/preprocess.md]
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>
#include <utility>

#include "bench/results_record.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/statistics.h"
#include "core/scene.h"
#include "core/volume_object.h"
#include "preprocess/preprocessor.h"

using namespace lucent;

int main(int argc, char** argv) {
    CLI::App app{"Lucent preprocessing benchmark (thesis Table 3.1)"};
    std::string sceneFile = std::string(LUCENT_SOURCE_DIR) + "/models/bunny.json";
    int samples = 50000, repeats = 3;
    std::vector<int> directions = {64, 128, 256};
    app.add_option("scene", sceneFile, "Scene whose first object is preprocessed");
    app.add_option("--samples", samples, "Target sample count of the direction rows (the preset keeps its own)");
    app.add_option("--repeats", repeats, "Runs per setting (the median is reported)");
    app.add_option("--directions", directions, "Heuristic direction counts")->delimiter(',');
    std::string recordFile;
    app.add_option("--record", recordFile, "Also write the results to this Markdown file (docs/results/)");
    CLI11_PARSE(app, argc, argv);
    try {
        if (!recordFile.empty()) checkWritable(recordFile);
        ResultsRecord out(argc, argv);
        const SceneDesc scene = parseScene(sceneFile);
        std::vector<std::string> warnings;
        const VolumeObject object(scene.objects.front(), warnings);
        out.print("scene %s, object %s: %zu triangles, target %d samples, %d repeats (median)\n\n",
                  std::filesystem::path(sceneFile).filename().c_str(), object.desc().name.c_str(),
                  object.mesh().triangles.size(), samples, repeats);
        out.tableHeader({"directions", "samples", "layers (s)", "optical depth for heuristic (s)", "divergence (s)",
                         "Poisson disks (s)", "SH projection (s)", "total (s)", "Mrays/s"},
                        std::vector<bool>(9, true));
        // As in thesis Table 3.1, one direction count drives both the heuristic
        // and the projection; then the default preset (`lucent preprocess`'s own
        // settings, which the speed goal of issue 43 is about).
        std::vector<std::pair<std::string, PreprocessSettings>> cases;
        for (int d : directions) {
            PreprocessSettings settings;
            settings.samples = samples;
            settings.heuristicDirections = d;
            settings.projectionDirections = d;
            cases.emplace_back(std::to_string(d), settings);
        }
        const PreprocessSettings preset = qualityPreset("default");
        cases.emplace_back("default preset: " + std::to_string(preset.samples / 1000) + "k samples, " +
                               std::to_string(preset.heuristicDirections) + " + " +
                               std::to_string(preset.projectionDirections),
                           preset);
        for (const auto& [label, settings] : cases) {
            std::vector<double> layers, moments, divergence, poisson, projection, total, rate;
            size_t count = 0;
            for (int r = 0; r < repeats; ++r) {
                PreprocessTimings t;
                count = preprocessObject(object, settings, &t).size();
                layers.push_back(t.layers);
                moments.push_back(t.firstMoments);
                divergence.push_back(t.divergence);
                poisson.push_back(t.poissonDisk);
                projection.push_back(t.projection);
                total.push_back(t.total());
                rate.push_back(double(t.heuristicRays + t.projectionRays) / (t.firstMoments + t.projection) / 1e6);
            }
            out.print("| %s | %zu | %.2f | %.2f | %.3f | %.2f | %.2f | %.2f | %.2f |\n", label.c_str(), count,
                      median(layers), median(moments), median(divergence), median(poisson), median(projection),
                      median(total), median(rate));
        }
        if (!recordFile.empty()) out.write(recordFile);
    } catch (const Error& e) {
        std::fprintf(stderr, "lucent-bench-preprocess: error: %s\n", e.what());
        return 1;
    }
    return 0;
}
