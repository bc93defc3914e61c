#include <tbb/global_control.h>

#include <cstdio>
#include <memory>

#include "apps/commands.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/image.h"
#include "core/scene.h"
#include "core/volume_object.h"
#include "reference/reference_renderer.h"
#include "runtime/render_ss.h"

namespace lucent {

Command addRenderCommand(CLI::App& app) {
    struct Options {
        std::string scene, output, method, backend;
        int width = 0, height = 0, threads = 0;
        bool noSurface = false;
        double tolerance = 1e-3;
        float exposure = 0.0f;
    };
    auto o = std::make_shared<Options>();
    CLI::App* sub = app.add_subcommand("render", "Render one frame of a scene offscreen");
    sub->add_option("scene", o->scene, "Scene file (JSON)")->required();
    sub->add_option("-o,--output", o->output, "Image to write: .png (tone-mapped), .pfm or .exr (linear)")->required();
    sub->add_option("--method", o->method, "ss, reference, path, lbl, mdom or auto (default: the scene's render.method)")
        ->check(CLI::IsMember({"ss", "reference", "path", "lbl", "mdom", "auto"}));
    sub->add_option("--backend", o->backend, "OpenGL backend for GL methods: osmesa or egl")->check(CLI::IsMember({"osmesa", "egl"}));
    sub->add_option("--width", o->width, "Image width (default: the scene camera's)")->check(CLI::Range(1, 16384));
    sub->add_option("--height", o->height, "Image height (default: the scene camera's)")->check(CLI::Range(1, 16384));
    sub->add_flag("--no-surface", o->noSurface, "Leave out the reflected surface term");
    sub->add_option("--tolerance", o->tolerance, "Relative quadrature tolerance of --method reference")->check(CLI::Range(1e-8, 0.5));
    sub->add_option("--threads", o->threads, "Worker threads (0: all cores)")->check(CLI::Range(0, 1024));
    sub->add_option("--exposure", o->exposure, "PNG exposure multiplier (default: automatic)")->check(CLI::Range(0.0, 1e30));
    return [o] {
        SceneDesc scene = parseScene(o->scene);
        checkWritable(o->output);
        if (o->width) scene.camera.width = o->width;
        if (o->height) scene.camera.height = o->height;
        std::string method = o->method.empty() ? scene.render.method : o->method;
        std::string why;
        if (method == "auto") {
            // Single scattering is the only fast method built so far; auto will weigh
            // the multiple-scattering methods against the albedo when they land.
            why = ", chosen by auto: the only interactive method built";
            method = "ss";
        }
        if (method != "reference" && method != "ss")
            throw Error("method '" + method + "' is not available in this build (available: ss, reference)");
        const GlBackend backend = parseGlBackend(o->backend);
        std::unique_ptr<tbb::global_control> threads;
        if (o->threads > 0)
            threads = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, o->threads);

        std::vector<std::string> warnings;
        const std::vector<VolumeObject> objects = loadObjects(scene, warnings);
        for (const auto& obj : objects)
            if (obj.desc().medium.ior != 1.0)
                warnings.push_back(obj.desc().name + ": ior " + std::to_string(obj.desc().medium.ior) +
                                   " is treated as index-matched (refraction is not simulated by single scattering)");
        printWarnings(warnings);
        const bool surface = !o->noSurface && scene.render.surface;
        Image image;
        if (method == "ss") {
            SsSettings settings;
            settings.backend = backend;
            settings.surface = surface;
            std::string used;
            image = renderSingleScattering(scene, objects, settings, &used);
            method += " on " + used;
        } else {
            ReferenceSettings settings;
            settings.tolerance = o->tolerance;
            settings.surface = surface;
            settings.threads = o->threads;
            image = ReferenceRenderer(scene, objects).render(settings);
        }
        writeImage(o->output, image, o->exposure);
        std::fprintf(stderr, "lucent: wrote %s (%dx%d, method %s%s)\n", o->output.c_str(), image.width, image.height,
                     method.c_str(), why.c_str());
    };
}

}  // namespace lucent
