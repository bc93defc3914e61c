#include <tbb/global_control.h>

#include <cstdio>
#include <memory>

#include "apps/commands.h"
#include "core/atomic_file.h"
#include "core/input_file.h"
#include "core/loaded_scene.h"
#include "core/sample_set.h"
#include "core/scene.h"
#include "core/volume_object.h"
#include "preprocess/preprocessor.h"

namespace lucent {

Command addPreprocessCommand(CLI::App& app) {
    struct Options {
        std::string scene, quality = "default", scheme = "lucent";
        int samples = 0, directions = 0, projectionDirections = 0, shOrder = 0, threads = 0;
        uint64_t seed = 1;
        double widthFactor = 0.0;
    };
    auto o = std::make_shared<Options>();
    CLI::App* sub =
        app.add_subcommand("preprocess", "Sample every translucent object of a scene and write its sample file");
    sub->add_option("scene", o->scene, "Scene file: JSON, or glTF 2.0 (.gltf, .glb; docs/gltf.md)")->required();
    sub->add_option("--quality", o->quality, "Preset: draft, default or high")
        ->check(CLI::IsMember({"draft", "default", "high"}));
    sub->add_option("--samples", o->samples, "Target sample count (overrides the preset)")
        ->check(CLI::Range(1, 50000000));
    sub->add_option("--directions", o->directions, "Directions d of the density heuristic")
        ->check(CLI::Range(6, 65536));
    sub->add_option("--projection-directions", o->projectionDirections, "Directions of the SH projection")
        ->check(CLI::Range(16, 65536));
    sub->add_option("--sh-order", o->shOrder, "SH bands (order L stores L*L coefficients)")
        ->check(CLI::Range(1, int(kMaxSampleShOrder)));
    sub->add_option("--seed", o->seed, "Random seed; the same seed gives the same file")->check(unsigned64());
    sub->add_option("--threads", o->threads, "Worker threads (0: all cores)")->check(CLI::Range(0, 1024));
    sub->add_option("--width-factor", o->widthFactor, "Gaussian FWHM as a multiple of the Poisson radius")
        ->check(finiteRange(0.05, 20.0));
    sub->add_option("--scheme", o->scheme,
                    "lucent (default) or published: the thesis's scheme as written, for comparison (docs/accuracy.md)")
        ->check(CLI::IsMember({"lucent", "published"}));
    return [o] {
        PreprocessSettings settings = qualityPreset(o->quality);
        if (o->scheme == "published") settings = publishedScheme(settings);
        if (o->samples) settings.samples = o->samples;
        if (o->directions) settings.heuristicDirections = o->directions;
        if (o->projectionDirections) settings.projectionDirections = o->projectionDirections;
        if (o->shOrder) settings.shOrder = o->shOrder;
        if (o->widthFactor > 0.0) settings.widthFactor = o->widthFactor;
        settings.seed = o->seed;
        std::unique_ptr<tbb::global_control> threads;
        if (o->threads > 0)
            threads = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, o->threads);

        // Samples live in each object's own space, made at its placement's scale:
        // its optical size (preprocess/preprocessor.h).
        const SceneDesc scene = parseScene(o->scene);
        // No sample file may replace an input of this run, nor serve two objects.
        std::vector<std::filesystem::path> outputs;
        for (const auto& object : scene.objects) outputs.push_back(object.samples);
        checkOutputsDistinct(outputs);
        for (const auto& output : outputs) {
            checkOutputIsNoInput(output, inputFilesOf(scene, false));
            checkWritable(output);
        }
        std::vector<std::string> warnings;
        const std::vector<VolumeObject> objects = loadObjects(scene, warnings);
        printWarnings(warnings);
        // Every object first, then every file: a failure on one object leaves no
        // sample file of another behind.
        std::vector<SampleSet> sets;
        for (const VolumeObject& object : objects) {
            PreprocessTimings timings;
            sets.push_back(preprocessObject(object, settings, &timings));
            std::fprintf(stderr,
                         "lucent: %s: %zu samples in %.2f s (layers %.2f, heuristic %.2f, divergence %.2f, "
                         "Poisson disks %.2f in %zu passes, SH %.2f)\n",
                         object.desc().name.c_str(), sets.back().size(), timings.total(), timings.layers,
                         timings.firstMoments, timings.divergence, timings.poissonDisk, timings.poissonPasses,
                         timings.projection);
        }
        for (size_t i = 0; i < objects.size(); ++i) {
            writeSampleFile(objects[i].desc().samples, sets[i]);
            std::fprintf(stderr, "lucent: %s: wrote %s\n", objects[i].desc().name.c_str(),
                         objects[i].desc().samples.string().c_str());
        }
    };
}

}  // namespace lucent
