#pragma once
// --method reference: the ReferenceRenderer behind the method interface.
#include "core/method.h"

namespace lucent {

class ReferenceMethod final : public Method {
public:
    explicit ReferenceMethod(double tolerance = 1e-3) : tolerance_(tolerance) {}
    // --tolerance.
    static std::vector<OptionSpec> options();
    static std::unique_ptr<Method> create(const MethodOptions& options);
    Image render(const LoadedScene& scene, const MethodSettings& settings) override;
    // Overlapping objects in a scene with a refracting boundary (as the path tracer).
    std::vector<std::string> limitations(const LoadedScene& scene, const MethodSettings&) const override;

private:
    double tolerance_;
};

}  // namespace lucent
