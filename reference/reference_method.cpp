#include "reference/reference_method.h"

#include "reference/reference_renderer.h"

namespace lucent {

Image ReferenceMethod::render(const LoadedScene& scene, const MethodSettings& settings) {
    ReferenceSettings reference;
    reference.tolerance = settings.tolerance;
    reference.surface = settings.surface;
    reference.threads = settings.threads;
    return ReferenceRenderer(scene.desc, scene.objects).render(reference);
}

}  // namespace lucent
