#include <tbb/global_control.h>

#include <cstdio>
#include <map>
#include <memory>
#include <optional>

#include "apps/commands.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/image.h"
#include "core/input_file.h"
#include "core/loaded_scene.h"
#include "core/progress.h"
#include "core/scene.h"
#include "apps/mpi_ranks.h"
#include "methods/method_table.h"

namespace lucent {

namespace {

struct RenderOptions {
    std::string scene, camera, output, method, seed = "1";
    int width = 0, height = 0, threads = 0;
    bool noSurface = false;
    float exposure = 0.0f;
    std::map<std::string, std::string> methodValues;  // the methods' own options, by name
    std::map<std::string, CLI::Option*> methodOptions;
};

// What one rank rendered, and how rank 0 names it.
struct Frame {
    Image image;
    std::string used, why;
    bool split = false;  // the ranks rendered shares of the rows, to be summed
};

// Parses, loads and renders on this rank: all of the image, its share of the
// rows (a method that splits them, under mpirun), or nothing (rank != 0 with a
// method that does not split).
Frame renderFrame(const RenderOptions& o, const Ranks& ranks) {
    const bool speaks = ranks.rank() == 0;  // warnings and progress from rank 0 only
    if (!speaks) setThreadProgressSink([](const std::string&, double, bool) {});
    const auto say = [&](const std::vector<std::string>& lines) {
        if (speaks) printWarnings(lines);
    };
    SceneDesc scene = parseScene(o.scene, o.camera);
    checkOutputIsNoInput(o.output, inputFilesOf(scene, true));
    checkWritable(o.output);
    if (o.width) scene.camera.width = o.width;
    if (o.height) scene.camera.height = o.height;
    const std::string requested = o.method.empty() ? scene.render.method : o.method;
    const ResolvedMethod method = resolveMethod(requested, scene);
    std::unique_ptr<tbb::global_control> threads;
    if (o.threads > 0)
        threads = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, o.threads);
    MethodSettings settings;
    settings.surface = !o.noSurface && scene.render.surface;
    settings.threads = o.threads;
    settings.seed = std::stoull(o.seed);
    Frame frame;
    frame.split = ranks.size() > 1 && method.entry->splitsRows;
    const bool shares = ranks.size() > 1 && method.entry->sharesSweeps;
    if (frame.split) settings.rows = RowShare{ranks.rank(), ranks.size()};
    if (shares) settings.peers = &ranks;
    if (ranks.size() > 1 && !frame.split && !shares)
        say({"--method " + method.entry->name + " does not share its work with the " + std::to_string(ranks.size()) +
             " ranks: rank 0 renders all of it (path and reference split the image, mdom its sweeps; docs/mpi.md)"});
    std::vector<std::string> ignored;
    const MethodOptions options = methodOptions(*method.entry, givenMethodOptions(o.methodValues, o.methodOptions),
                                                !method.reason.empty(), ignored);
    say(ignored);
    const std::unique_ptr<Method> renderer = method.entry->create(options);
    if (!frame.split && !shares && !speaks) return frame;
    if (speaks || frame.split) renderer->prepare(scene, settings);  // while the scene loads; only where it draws
    LoadedScene loaded = loadScene(scene, method.entry->needsSamples);
    say(loaded.warnings);
    say(renderer->limitations(loaded, settings));  // before the work, not after
    std::string servedBy;
    frame.image = renderWith(*method.entry, *renderer, loaded, settings, &servedBy);
    frame.used = method.entry->name + (servedBy.empty() ? "" : " on " + servedBy) +
                 (frame.split || shares ? ", " + std::to_string(ranks.size()) + " ranks" : "");
    frame.why = method.reason.empty() ? "" : ", chosen by auto: " + method.reason;
    return frame;
}

void writeFrame(const RenderOptions& o, const Frame& frame) {
    size_t nonFinite = 0;
    for (const auto& p : frame.image.pixels)
        nonFinite += std::isfinite(p.r) && std::isfinite(p.g) && std::isfinite(p.b) ? 0 : 1;
    if (nonFinite > 0)
        printWarnings({std::to_string(nonFinite) + " pixel(s) overflowed the single-precision range and are "
                                                   "written as 0 (lower the light or sigma_t; docs/robustness.md)"});
    writeImage(o.output, frame.image, o.exposure);
    std::fprintf(stderr, "lucent: wrote %s (%dx%d, method %s%s)\n", o.output.c_str(), frame.image.width,
                 frame.image.height, frame.used.c_str(), frame.why.c_str());
}

}  // namespace

Command addRenderCommand(CLI::App& app) {
    auto o = std::make_shared<RenderOptions>();
    CLI::App* sub = app.add_subcommand("render",
                                       "Render one frame of a scene offscreen. Under mpirun, path and reference "
                                       "share the image's rows among the ranks and mdom its sweeps (a build with "
                                       "OpenMPI, libopenmpi-dev; docs/mpi.md)");
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
        Ranks ranks;
        std::optional<Frame> frame;
        std::string failure;
        try {
            frame = renderFrame(*o, ranks);
        } catch (const Error& e) {
            failure = e.what();
        } catch (const std::bad_alloc&) {
            failure = "out of memory";
        } catch (const PeerFailed&) {  // the rank that failed says why
        }
        // Every rank reaches this point, failed or not: none is left waiting.
        ranks.leaveIfAnyFailed(failure);
        if (frame->split) ranks.sumIntoRankZero(frame->image);
        if (ranks.rank() == 0) writeFrame(*o, *frame);
    };
}

}  // namespace lucent
