#include "methods/grid_method.h"

#include "runtime/ss_method.h"

namespace lucent {

std::vector<std::string> GridMethod::limitations(const LoadedScene& scene, const MethodSettings& settings) const {
    return SsMethod::sampleLimitations(scene, settings);
}

Image GridMethod::render(const LoadedScene& scene, const MethodSettings& settings) {
    std::string device, backend;
    const std::vector<ScatteringGrid> grids = solveGrids(scene, settings, device);
    Image image = renderSingleScattering(scene, settings, grids, backend);
    servedBy_ = backend + " + OpenCL '" + device + "'";
    return image;
}

}  // namespace lucent
