#include <memory>

#include "apps/commands.h"
#include "core/scene.h"
#include "viewer/viewer.h"

namespace lucent {

Command addViewCommand(CLI::App& app) {
    struct Options {
        std::string scene, camera, script, screenshot;
        int width = 0, height = 0;
    };
    auto o = std::make_shared<Options>();
    CLI::App* sub = app.add_subcommand("view", "Interactive multi-light viewer (GLFW window)");
    sub->add_option(
           "scene", o->scene,
           "Scene file: JSON, or glTF 2.0 (.gltf, .glb; docs/gltf.md); its objects must have been preprocessed")
        ->required();
    sub->add_option("--camera", o->camera,
                    "glTF scenes: the camera to look through, by name (default: the file's first)");
    sub->add_option("--script", o->script, "Run viewer commands from a file, one per frame (docs/viewer.md)");
    sub->add_option("--screenshot", o->screenshot, "After the script, save the view to this image and exit");
    sub->add_option("--width", o->width, "Window width")->check(CLI::Range(16, 8192));
    sub->add_option("--height", o->height, "Window height")->check(CLI::Range(16, 8192));
    return [o] {
        ViewerOptions options;
        options.script = o->script;
        options.screenshot = o->screenshot;
        options.width = o->width;
        options.height = o->height;
        runViewer(parseScene(o->scene, o->camera), options);
    };
}

}  // namespace lucent
