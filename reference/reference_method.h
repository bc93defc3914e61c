#pragma once
// --method reference: the ReferenceRenderer behind the method interface.
#include "core/method.h"

namespace lucent {

class ReferenceMethod final : public Method {
public:
    Image render(const LoadedScene& scene, const MethodSettings& settings) override;
};

}  // namespace lucent
