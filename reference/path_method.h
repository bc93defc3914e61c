#pragma once
// --method path: the PathTracer behind the method interface.
#include "core/method.h"

namespace lucent {

class PathMethod final : public Method {
public:
    Image render(const LoadedScene& scene, const MethodSettings& settings) override;
    // Objects whose boxes overlap in a scene with a refracting boundary (each
    // boundary must separate one medium from the air there).
    std::vector<std::string> limitations(const LoadedScene& scene, const MethodSettings& settings) const override;
};

}  // namespace lucent
