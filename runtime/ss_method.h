#pragma once
// --method ss: the scene's objects with their sample sets, drawn offscreen by the
// ScatteringRenderer through EGL or OSMesa.
#include "core/method.h"

namespace lucent {

class SsMethod final : public Method {
public:
    Image render(const LoadedScene& scene, const MethodSettings& settings) override;
    std::string servedBy() const override { return backend_; }  // "egl" or "osmesa"

private:
    std::string backend_;
};

}  // namespace lucent
