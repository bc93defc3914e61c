#pragma once
// ss's frame as the viewer draws it: drawn again with everything cached (the
// light, through a boundary too, and the view's stretches, traced by the
// warm-up), the median of frames at frameSize x frameSize, in ms; or of two
// scenes' frames drawn in turn. The scene's first object with its samples, lit
// by the scene's lights and environment as ss lights it.
#include <utility>
#include <vector>

#include "core/loaded_scene.h"
#include "core/statistics.h"
#include "runtime/offscreen_context.h"
#include "runtime/offscreen_frame.h"
#include "runtime/opengl.h"
#include "runtime/scattering_renderer.h"
#include "runtime/ss_method.h"

namespace lucent {

namespace detail {

// Untimed frames before the timed ones: the first draws trace the light and the view.
inline constexpr int kWarmupFrames = 3;

// An ss renderer of the scene's first object, lit as ss lights it, its view at
// frameSize and its draw options (no surface term).
struct SsFrameScene {
    ScatteringRenderer renderer;
    ViewSetup view;
    DrawOptions options;
    SsFrameScene(const LoadedScene& loaded, int frameSize, const SsOptions& ss) {
        renderer.addObject(translucentObjectFor(loaded.objects[0], loaded.samples[0]));
        setSsLights(renderer, loaded, ss);
        Camera camera = loaded.desc.camera;
        camera.width = camera.height = frameSize;
        view = viewSetupFor(camera, loaded.bounds());
        options.surface = false;
        options.tracedLight = ss.tracedLight;
    }
    void draw() { renderer.draw(view, options); }
};

}  // namespace detail

inline double ssFrameMs(const LoadedScene& loaded, int frameSize, int frames, const SsOptions& ss = {}) {
    const auto context = OffscreenContext::create(GlBackend::Auto);
    OffscreenFrame frame(frameSize, frameSize);
    detail::SsFrameScene scene(loaded, frameSize, ss);
    return 1e3 * medianFrameSeconds(
                     detail::kWarmupFrames, frames, [&] { frame.bindAndClear(); }, [&] { scene.draw(); });
}

// The frames of two scenes drawn in turn, a frame of one then a frame of the
// other, the median of each in ms: their ratio is measured over the same
// seconds of a shared machine, where frames timed minutes apart moved it by a fifth.
inline std::pair<double, double> ssFrameMsInTurn(const LoadedScene& a, const LoadedScene& b, int frameSize, int frames,
                                                 const SsOptions& ss = {}) {
    const auto context = OffscreenContext::create(GlBackend::Auto);
    OffscreenFrame frame(frameSize, frameSize);
    detail::SsFrameScene first(a, frameSize, ss), second(b, frameSize, ss);
    std::vector<double> times[2];
    for (int f = 0; f < detail::kWarmupFrames + frames; ++f)
        for (int k = 0; k < 2; ++k) {
            detail::SsFrameScene& scene = k == 0 ? first : second;
            frame.bindAndClear();
            const double seconds = timeGlWork([&] { scene.draw(); });
            if (f >= detail::kWarmupFrames) times[k].push_back(seconds);
        }
    return {1e3 * median(times[0]), 1e3 * median(times[1])};
}

}  // namespace lucent
