#include <tbb/global_control.h>

#include <cstdio>
#include <map>
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
        std::string scene, camera, output, method, seed = "1";
        int width = 0, height = 0, threads = 0;
        bool noSurface = false;
        float exposure = 0.0f;
        std::map<std::string, std::string> methodValues;  // the methods' own options, by name
        std::map<std::string, CLI::Option*> methodOptions;
    };
    auto o = std::make_shared<Options>();
    CLI::App* sub = app.add_subcommand("render", "Render one frame of a scene offscreen");
    sub->add_option("scene", o->scene, "Scene file: JSON, or glTF 2.0 (.gltf, .glb; docs/gltf.md)")->required();
    sub->add_option("--camera", o->camera,
                    "glTF scenes: the camera to look through, by name (default: the file's first)");
    sub->add_option("-o,--output", o->output, "Image to write: .png (tone-mapped), .pfm or .exr (linear)")->required();
    std::string methodHelp = "Rendering method (default: the scene's render.method):";
    for (const MethodEntry& m : methodTable()) methodHelp += "\n  " + m.name + ": " + m.summary;
    methodHelp += "\n  auto: picks one for the scene and says why";
    sub->add_option("--method", o->method, methodHelp)->check(CLI::IsMember(methodNames()));
    sub->add_option("--width", o->width, "Image width (default: the scene camera's)")->check(CLI::Range(1, 16384));
    sub->add_option("--height", o->height, "Image height (default: the scene camera's)")->check(CLI::Range(1, 16384));
    sub->add_flag("--no-surface", o->noSurface, "Leave out the reflected surface term");
    sub->add_option("--threads", o->threads, "Worker threads (0: all cores)")->check(CLI::Range(0, 1024));
    sub->add_option("--seed", o->seed, "Random seed; the same seed gives the same image")->check(unsigned64());
    sub->add_option("--exposure", o->exposure, "PNG exposure multiplier (default: automatic)")
        ->check(finiteRange(0.0, 1e30));
    addMethodOptions(*sub, o->methodValues, o->methodOptions);
    return [o] {
        SceneDesc scene = parseScene(o->scene, o->camera);
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
        settings.threads = o->threads;
        settings.seed = std::stoull(o->seed);
        std::vector<std::string> ignored;
        const MethodOptions options = methodOptions(
            *method.entry, givenMethodOptions(o->methodValues, o->methodOptions), !method.reason.empty(), ignored);
        printWarnings(ignored);
        const std::unique_ptr<Method> renderer = method.entry->create(options);
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
