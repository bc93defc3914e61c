#pragma once
// --method mdom: single scattering plus the light scattered twice or more,
// solved per object by the modified discrete ordinates method of thesis
// chapter 5 (hybrid/mdom_scattering.h), baked towards the camera. Unlike lbl's
// lattice it follows forward-scattering media.
#include "methods/grid_method.h"

namespace lucent {

class MdomMethod final : public GridMethod {
public:
    explicit MdomMethod(const MethodOptions& options);
    // GridMethod's, --directions and --moments.
    static std::vector<OptionSpec> options();
    static std::unique_ptr<Method> create(const MethodOptions& options) {
        return std::make_unique<MdomMethod>(options);
    }
    std::vector<std::string> limitations(const LoadedScene& scene, const MethodSettings& settings) const override;

private:
    std::vector<ScatteringGrid> solveGrids(const LoadedScene& scene, const MethodSettings& settings,
                                           std::string& device) override;
    int directions_, moments_;
    double devicePool_;  // share of the sweeps' volumes on the device; 0: all, unblocked
};

}  // namespace lucent
