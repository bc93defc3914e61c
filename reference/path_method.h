#pragma once
// --method path: the PathTracer behind the method interface.
#include "core/method.h"

namespace lucent {

class PathMethod final : public Method {
public:
    Image render(const LoadedScene& scene, const MethodSettings& settings) override;
};

}  // namespace lucent
