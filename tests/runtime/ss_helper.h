#pragma once
// --method ss on a scene whose objects' sample files are written: what
// `lucent render --method ss` does, through the method interface.
#include <string>

#include "core/loaded_scene.h"
#include "core/method.h"
#include "runtime/ss_method.h"

namespace lucent::test {

inline Image renderSs(const SceneDesc& scene, bool surface = true, const std::string& backend = "") {
    const LoadedScene loaded = loadScene(scene, true);
    MethodSettings settings;
    settings.surface = surface;
    settings.backend = backend;
    return SsMethod().render(loaded, settings);
}

}  // namespace lucent::test
