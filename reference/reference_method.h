#pragma once
// --method reference: the ReferenceRenderer behind the method interface.
#include "core/method.h"

namespace lucent {

class ReferenceMethod final : public Method {
public:
    Image render(const LoadedScene& scene, const MethodSettings& settings) override;
    std::vector<std::string> limitations(const LoadedScene& scene, const MethodSettings&) const override {
        return indexMatchedWarnings(scene, "reference");
    }
};

}  // namespace lucent
