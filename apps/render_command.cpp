#include <tbb/global_control.h>

#include <cstdio>
#include <memory>

#include "apps/commands.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/image.h"
#include "core/input_file.h"
#include "core/loaded_scene.h"
#include "core/scene.h"
#include "methods/method_table.h"

namespace lucent {

Command addRenderCommand(CLI::App& app) {
    struct Options {
        std::string scene, output, method, backend, light = "traced";
        int width = 0, height = 0, threads = 0, samples = 64, maxScatter = 1 << 20, grid = 64, directions = 48,
            moments = 16;
        double noise = 0.0;
        std::string seed = "1";
        bool noSurface = false;
        double tolerance = 1e-3;
        float exposure = 0.0f;
    };
    auto o = std::make_shared<Options>();
    CLI::App* sub = app.add_subcommand("render", "Render one frame of a scene offscreen");
    sub->add_option("scene", o->scene, "Scene file (JSON)")->required();
    sub->add_option("-o,--output", o->output, "Image to write: .png (tone-mapped), .pfm or .exr (linear)")->required();
    std::string methodHelp = "Rendering method (default: the scene's render.method):";
    for (const MethodEntry& m : methodTable()) methodHelp += "\n  " + m.name + ": " + m.summary;
    methodHelp += "\n  auto: picks one for the scene and says why";
    sub->add_option("--method", o->method, methodHelp)->check(CLI::IsMember(methodNames()));
    sub->add_option("--backend", o->backend, "OpenGL backend for GL methods: osmesa or egl")
        ->check(CLI::IsMember({"osmesa", "egl"}));
    sub->add_option("--width", o->width, "Image width (default: the scene camera's)")->check(CLI::Range(1, 16384));
    sub->add_option("--height", o->height, "Image height (default: the scene camera's)")->check(CLI::Range(1, 16384));
    sub->add_flag("--no-surface", o->noSurface, "Leave out the reflected surface term");
    sub->add_option("--light", o->light,
                    "Sample methods: the light reaching each sample traced through the objects (traced, default) or "
                    "read from its SH attenuation (sh: the thesis; blurs narrow shadows, no shadows between objects)")
        ->check(CLI::IsMember({"traced", "sh"}));
    sub->add_option("--tolerance", o->tolerance, "Relative quadrature tolerance of --method reference")
        ->check(finiteRange(1e-8, 0.5));
    sub->add_option("--threads", o->threads, "Worker threads (0: all cores)")->check(CLI::Range(0, 1024));
    sub->add_option("--samples", o->samples, "Paths per pixel of --method path (default 64)")
        ->check(CLI::Range(1, 1 << 24));
    sub->add_option("--grid", o->grid, "Voxels along each object's longest side for --method lbl and mdom (default 64)")
        ->check(CLI::Range(8, 1024));
    sub->add_option("--directions", o->directions,
                    "Propagation directions of --method mdom: 24, 48, 80, 120 or 168 (default 48)")
        ->check(CLI::IsMember({24, 48, 80, 120, 168}));
    sub->add_option("--moments", o->moments,
                    "Spherical-harmonic moments of the scattering source per voxel of --method mdom: 4, 9, 16, 25 "
                    "or 36 (default 16)")
        ->check(CLI::IsMember({4, 9, 16, 25, 36}));
    sub->add_option("--noise", o->noise,
                    "--method path: sample each pixel until the standard error of its mean is at most this share of "
                    "it, up to --samples (0: always --samples)")
        ->check(finiteRange(0.0, 1.0));
    sub->add_option("--max-scatter", o->maxScatter,
                    "Collisions per path of --method path (1: single scattering; default unlimited)")
        ->check(CLI::Range(1, 1 << 20));
    sub->add_option("--seed", o->seed, "Random seed of --method path; the same seed gives the same image")
        ->check(unsigned64());
    sub->add_option("--exposure", o->exposure, "PNG exposure multiplier (default: automatic)")
        ->check(finiteRange(0.0, 1e30));
    return [o] {
        SceneDesc scene = parseScene(o->scene);
        checkOutputIsNoInput(o->output, inputFilesOf(scene, true));
        checkWritable(o->output);
        if (o->width) scene.camera.width = o->width;
        if (o->height) scene.camera.height = o->height;
        const std::string requested = o->method.empty() ? scene.render.method : o->method;
        const ResolvedMethod method = resolveMethod(requested, scene);
        std::unique_ptr<tbb::global_control> threads;
        if (o->threads > 0)
            threads = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, o->threads);
        MethodSettings settings;
        settings.surface = !o->noSurface && scene.render.surface;
        settings.tolerance = o->tolerance;
        settings.threads = o->threads;
        settings.backend = o->backend;
        settings.tracedLight = o->light == "traced";
        settings.samplesPerPixel = o->samples;
        settings.maxScatter = o->maxScatter;
        settings.gridResolution = o->grid;
        settings.directions = o->directions;
        settings.moments = o->moments;
        settings.noiseTarget = o->noise;
        settings.seed = std::stoull(o->seed);
        const std::unique_ptr<Method> renderer = method.entry->create();
        renderer->prepare(scene, settings);  // while the scene loads
        LoadedScene loaded = loadScene(scene, method.entry->needsSamples);
        printWarnings(loaded.warnings);
        printWarnings(renderer->limitations(loaded, settings));  // before the work, not after
        std::string servedBy;
        const Image image = renderWith(*method.entry, *renderer, loaded, settings, &servedBy);
        const std::string used = method.entry->name + (servedBy.empty() ? "" : " on " + servedBy);
        const std::string why = method.reason.empty() ? "" : ", chosen by auto: " + method.reason;
        size_t nonFinite = 0;
        for (const auto& p : image.pixels)
            nonFinite += std::isfinite(p.r) && std::isfinite(p.g) && std::isfinite(p.b) ? 0 : 1;
        if (nonFinite > 0)
            printWarnings({std::to_string(nonFinite) +
                           " pixel(s) overflowed the single-precision range and are "
                           "written as 0 (lower the light or sigma_t; docs/robustness.md)"});
        writeImage(o->output, image, o->exposure);
        std::fprintf(stderr, "lucent: wrote %s (%dx%d, method %s%s)\n", o->output.c_str(), image.width, image.height,
                     used.c_str(), why.c_str());
    };
}

}  // namespace lucent
