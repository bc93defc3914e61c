#pragma once
// The shape lbl and mdom share: single scattering from the samples, exactly as
// --method ss draws it, plus per object a grid of the light scattered twice or
// more, solved by a hybrid of hybrid/ on OpenCL and added by the runtime's view
// pass. A subclass solves the grids; this draws them. Lives above both stages:
// the hybrid never sees OpenGL and the runtime never sees OpenCL.
#include <algorithm>
#include <string>
#include <vector>

#include "core/method.h"
#include "core/scattering_grid.h"
#include "runtime/ss_method.h"

namespace lucent {

// The grids take an environment as at most this many directional lights (ss's
// --env-lights, up to it), since the light scattered twice or more is smooth:
// under a sky with a sun, lbl and mdom with 16 stay within 2 points of 64, at
// 33-67% of its solve's time, and with 4 are 13-14% off on the sphere
// (docs/results/environment.md, lucent-bench-environment).
inline constexpr int kGridEnvironmentLights = 16;

class GridMethod : public Method {
public:
    // ss's options and --grid, which every grid method takes.
    static std::vector<OptionSpec> options();

    Image render(const LoadedScene& scene, const MethodSettings& settings) final;
    std::string servedBy() const final { return servedBy_; }
    std::vector<std::string> limitations(const LoadedScene& scene, const MethodSettings& settings) const override;

protected:
    explicit GridMethod(const MethodOptions& options)
        : ss_(SsOptions::from(options)), resolution_(options.integer("grid")) {}
    int resolution() const { return resolution_; }
    // The directional lights an environment becomes in the grids' solve.
    int environmentLights() const { return std::min(ss_.environmentLights, kGridEnvironmentLights); }
    // One grid per object of the scene, in order, each reported on one line;
    // device receives the OpenCL device's name.
    virtual std::vector<ScatteringGrid> solveGrids(const LoadedScene& scene, const MethodSettings& settings,
                                                   std::string& device) = 0;

private:
    SsOptions ss_;
    int resolution_;
    std::string servedBy_;
};

}  // namespace lucent
