#include "methods/grid_method.h"

#include "runtime/ss_method.h"

namespace lucent {

std::vector<OptionSpec> GridMethod::options() {
    std::vector<OptionSpec> out = SsOptions::specs();
    out.push_back(OptionSpec::integer("grid", 64, 8, 1024,
                                      "voxels along each object's longest side; memory and time grow as its cube"));
    return out;
}

std::vector<std::string> GridMethod::limitations(const LoadedScene& scene, const MethodSettings&) const {
    return SsMethod::sampleLimitations(scene, ss_);
}

Image GridMethod::render(const LoadedScene& scene, const MethodSettings& settings) {
    std::string device, backend;
    const std::vector<ScatteringGrid> grids = solveGrids(scene, settings, device);
    // Sharing the solve with the ranks of an MPI job, only rank 0 holds the grids and draws.
    if (settings.peers && settings.peers->rank() != 0) return Image{};
    Image image = renderSingleScattering(scene, settings, ss_, grids, backend);
    servedBy_ = backend + " + OpenCL '" + device + "'";
    return image;
}

}  // namespace lucent
