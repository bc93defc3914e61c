#pragma once
// --method ss on a scene whose objects' sample files are written: what
// `lucent render --method ss` does, through the method interface.
#include <string>

#include "core/image_compare.h"
#include "core/loaded_scene.h"
#include "core/method.h"
#include "preprocess/preprocessor.h"
#include "reference/reference_renderer.h"
#include "runtime/ss_method.h"

namespace lucent::test {

inline Image renderSs(const SceneDesc& scene, bool surface = true, const std::string& backend = "",
                      bool tracedLight = true) {
    const LoadedScene loaded = loadScene(scene, true);
    MethodSettings settings;
    settings.surface = surface;
    return SsMethod({tracedLight, backend}).render(loaded, settings);
}

// Every object of scene preprocessed at default quality into its sample file,
// then ss against the exact reference (no surface term), margin pixels inside
// the silhouette.
inline ImageError ssAgainstReference(const SceneDesc& scene, int margin = 0) {
    std::vector<std::string> warnings;
    const auto objects = loadObjects(scene, warnings);
    for (const VolumeObject& o : objects)
        writeSampleFile(o.desc().samples, preprocessObject(o, qualityPreset("default")));
    ReferenceSettings reference;
    reference.tolerance = 1e-4;
    reference.surface = false;
    return compareImages(renderSs(scene, false), ReferenceRenderer(scene, objects).render(reference), margin);
}

}  // namespace lucent::test
