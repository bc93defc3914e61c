#include "reference/path_method.h"

#include "reference/path_tracer.h"

namespace lucent {

Image PathMethod::render(const LoadedScene& scene, const MethodSettings& settings) {
    PathSettings path;
    path.samplesPerPixel = settings.samplesPerPixel;
    path.noiseTarget = settings.noiseTarget;
    path.maxScatter = settings.maxScatter;
    path.seed = settings.seed;
    path.threads = settings.threads;
    path.surface = settings.surface;
    return PathTracer(scene.desc, scene.objects).render(path).mean;
}

}  // namespace lucent
