#pragma once
// --method lbl: single scattering plus the light scattered twice or more,
// solved per object by the hybrid of thesis chapter 4 (photon marching +
// Lattice-Boltzmann lighting, hybrid/multiple_scattering.h).
#include "methods/grid_method.h"

namespace lucent {

class LblMethod final : public GridMethod {
public:
    explicit LblMethod(const MethodOptions& options) : GridMethod(options) {}
    static std::unique_ptr<Method> create(const MethodOptions& options) { return std::make_unique<LblMethod>(options); }
    std::vector<std::string> limitations(const LoadedScene& scene, const MethodSettings& settings) const override;

private:
    std::vector<ScatteringGrid> solveGrids(const LoadedScene& scene, const MethodSettings& settings,
                                           std::string& device) override;
};

}  // namespace lucent
