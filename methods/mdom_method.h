#pragma once
// --method mdom: single scattering from the samples (as --method ss) plus the
// light scattered twice or more, solved per object by the modified discrete
// ordinates method of thesis chapter 5 on OpenCL (hybrid/) and added by the
// runtime's view pass, as lbl's. Unlike lbl's lattice it follows
// forward-scattering media (g up to 0.9).
#include "core/method.h"

namespace lucent {

class MdomMethod final : public Method {
public:
    Image render(const LoadedScene& scene, const MethodSettings& settings) override;
    std::string servedBy() const override { return servedBy_; }
    std::vector<std::string> limitations(const LoadedScene& scene) const override;

private:
    std::string servedBy_;
};

}  // namespace lucent
