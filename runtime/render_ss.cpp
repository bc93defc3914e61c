#include "runtime/render_ss.h"

#include "core/error.h"
#include "core/sample_set.h"
#include "runtime/offscreen_frame.h"
#include "runtime/scattering_renderer.h"

namespace lucent {

SampleSet loadSamplesFor(const VolumeObject& object) {
    SampleSet s = readSampleFile(object.desc().samples);
    if (s.sceneFingerprint != object.desc().fingerprint)
        throw Error(object.desc().samples.string(), "sample file was made for a different mesh or medium than object '" +
                                                        object.desc().name + "'; run lucent preprocess again");
    return s;
}

Image renderSingleScattering(const SceneDesc& scene, const std::vector<VolumeObject>& objects,
                             const SsSettings& settings, std::string* backendUsed) {
    std::vector<SampleSet> sampleSets;
    Bounds3 bounds;
    for (const VolumeObject& o : objects) {
        sampleSets.push_back(loadSamplesFor(o));
        bounds.extend(o.mesh().bounds().min);
        bounds.extend(o.mesh().bounds().max);
    }
    const auto context = OffscreenContext::create(settings.backend);
    if (backendUsed) *backendUsed = context->backendName();
    const ViewSetup view = viewSetupFor(scene.camera, bounds);
    OffscreenFrame frame(view.width, view.height);
    ScatteringRenderer renderer(settings.cutoff);
    for (size_t i = 0; i < objects.size(); ++i) {
        renderer.addObject(translucentObjectFor(objects[i], sampleSets[i]));
    }
    renderer.setLights(scene.lights);
    frame.bindAndClear();
    DrawOptions options;
    options.surface = settings.surface;
    renderer.draw(view, options);
    return frame.read();
}

}  // namespace lucent
