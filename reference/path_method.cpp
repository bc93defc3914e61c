#include "reference/path_method.h"

#include <algorithm>

#include "core/sphere_light.h"
#include "reference/path_tracer.h"

namespace lucent {

std::vector<std::string> PathMethod::limitations(const LoadedScene& scene, const MethodSettings&) const {
    std::vector<std::string> out = overlappingRefractors(scene, "the path tracer");
    for (std::string& line : sphereLightsThroughBoundaries(scene.desc)) out.push_back(std::move(line));
    return out;
}

std::vector<std::string> overlappingRefractors(const LoadedScene& scene, const std::string& method) {
    std::vector<std::string> out;
    const auto& objects = scene.objects;
    const bool refracting =
        std::any_of(objects.begin(), objects.end(), [](const VolumeObject& o) { return o.desc().medium.ior != 1.0; });
    if (!refracting) return out;
    for (size_t i = 0; i < objects.size(); ++i)
        for (size_t j = i + 1; j < objects.size(); ++j) {
            const Bounds3 a = objects[i].mesh().bounds(), b = objects[j].mesh().bounds();
            if (glm::all(glm::lessThan(a.min, b.max)) && glm::all(glm::lessThan(b.min, a.max)))
                out.push_back("objects '" + objects[i].desc().name + "' and '" + objects[j].desc().name +
                              "' may overlap: with a refracting boundary in the scene " + method +
                              " takes each "
                              "boundary to separate one medium from the air, and is wrong where objects overlap");
        }
    return out;
}

std::vector<OptionSpec> PathMethod::options() {
    const PathSettings defaults;
    return {OptionSpec::integer("samples", defaults.samplesPerPixel, 1, 1 << 24,
                                "paths per pixel (with --noise: the most a pixel takes); the noise falls as one over "
                                "their square root"),
            OptionSpec::real("noise", defaults.noiseTarget, 0.0, 1.0,
                             "sample each pixel until the standard error of its mean is at most this share of it, "
                             "up to --samples (0: always --samples)"),
            OptionSpec::integer("max-scatter", defaults.maxScatter, 1, 1 << 20,
                                "collisions gathered per path (1: single scattering, the truth of ss)")};
}

std::unique_ptr<Method> PathMethod::create(const MethodOptions& options) {
    PathSettings paths;
    paths.samplesPerPixel = options.integer("samples");
    paths.noiseTarget = options.real("noise");
    paths.maxScatter = options.integer("max-scatter");
    return std::make_unique<PathMethod>(paths);
}

Image PathMethod::render(const LoadedScene& scene, const MethodSettings& settings) {
    PathSettings path = paths_;
    path.seed = settings.seed;
    path.threads = settings.threads;
    path.surface = settings.surface;
    path.rows = settings.rows;
    return PathTracer(scene.desc, scene.objects, scene.environment.get()).render(path).mean;
}

}  // namespace lucent
