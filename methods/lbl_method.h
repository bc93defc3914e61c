#pragma once
// --method lbl: single scattering from the samples (as --method ss) plus the
// light scattered twice or more, solved per object by the hybrid of thesis
// chapter 4 on OpenCL (photon marching + Lattice-Boltzmann lighting, hybrid/)
// and added by the runtime's view pass. Lives above both stages: the hybrid
// never sees OpenGL and the runtime never sees OpenCL.
#include "core/method.h"

namespace lucent {

class LblMethod final : public Method {
public:
    Image render(const LoadedScene& scene, const MethodSettings& settings) override;
    std::string servedBy() const override { return servedBy_; }
    std::vector<std::string> limitations(const LoadedScene& scene) const override;

private:
    std::string servedBy_;
};

}  // namespace lucent
