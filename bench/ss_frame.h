#pragma once
// ss's frame as the viewer draws it: drawn again with everything cached (the
// light, through a boundary too, and the view's stretches, traced by the
// warm-up), the median of frames at frameSize x frameSize, in ms. The scene's
// first object with its samples, lit by the scene's lights and environment as ss lights it.
#include "core/loaded_scene.h"
#include "runtime/offscreen_context.h"
#include "runtime/offscreen_frame.h"
#include "runtime/opengl.h"
#include "runtime/scattering_renderer.h"
#include "runtime/ss_method.h"

namespace lucent {

inline double ssFrameMs(const LoadedScene& loaded, int frameSize, int frames, const SsOptions& ss = {}) {
    const auto context = OffscreenContext::create(GlBackend::Auto);
    OffscreenFrame frame(frameSize, frameSize);
    ScatteringRenderer renderer;
    renderer.addObject(translucentObjectFor(loaded.objects[0], loaded.samples[0]));
    setSsLights(renderer, loaded, ss);
    Camera camera = loaded.desc.camera;
    camera.width = camera.height = frameSize;
    const ViewSetup view = viewSetupFor(camera, loaded.bounds());
    DrawOptions options;
    options.surface = false;
    options.tracedLight = ss.tracedLight;
    return 1e3 * medianFrameSeconds(
                     3, frames, [&] { frame.bindAndClear(); }, [&] { renderer.draw(view, options); });
}

}  // namespace lucent
