#include "runtime/ss_method.h"

#include "core/error.h"
#include "runtime/offscreen_context.h"
#include "runtime/offscreen_frame.h"
#include "runtime/scattering_renderer.h"

namespace lucent {

Image SsMethod::render(const LoadedScene& scene, const MethodSettings& settings) {
    if (!scene.hasSamples()) throw Error(scene.desc.file.string(), "--method ss needs the objects' sample sets");
    const auto context = OffscreenContext::create(parseGlBackend(settings.backend));
    backend_ = context->backendName();
    const ViewSetup view = viewSetupFor(scene.desc.camera, scene.bounds());
    OffscreenFrame frame(view.width, view.height);
    ScatteringRenderer renderer(settings.cutoff);
    for (size_t i = 0; i < scene.objects.size(); ++i)
        renderer.addObject(translucentObjectFor(scene.objects[i], scene.samples[i]));
    renderer.setLights(scene.desc.lights);
    frame.bindAndClear();
    DrawOptions options;
    options.surface = settings.surface;
    renderer.draw(view, options);
    return frame.read();
}

}  // namespace lucent
