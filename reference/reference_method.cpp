#include "reference/reference_method.h"

#include <algorithm>

#include "core/sphere_light.h"
#include "reference/path_method.h"
#include "reference/reference_renderer.h"

namespace lucent {

std::vector<OptionSpec> ReferenceMethod::options() {
    return {OptionSpec::real("tolerance", ReferenceSettings().tolerance, 1e-8, 0.5,
                             "relative error target of each pixel's integral; the time grows as it shrinks")};
}

std::unique_ptr<Method> ReferenceMethod::create(const MethodOptions& options) {
    return std::make_unique<ReferenceMethod>(options.real("tolerance"));
}

std::vector<std::string> ReferenceMethod::limitations(const LoadedScene& scene, const MethodSettings&) const {
    std::vector<std::string> out = overlappingRefractors(scene, "the reference");
    for (std::string& line : sphereLightsThroughBoundaries(scene.desc)) out.push_back(std::move(line));
    return out;
}

Image ReferenceMethod::render(const LoadedScene& scene, const MethodSettings& settings) {
    ReferenceSettings reference;
    reference.tolerance = tolerance_;
    reference.surface = settings.surface;
    reference.threads = settings.threads;
    reference.rows = settings.rows;
    return ReferenceRenderer(scene.desc, scene.objects, scene.environment.get()).render(reference);
}

}  // namespace lucent
