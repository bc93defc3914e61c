#pragma once
// --method ss: the scene's objects with their sample sets, drawn offscreen by the
// ScatteringRenderer through EGL or OSMesa.
#include "core/method.h"

namespace lucent {

class SsMethod final : public Method {
public:
    Image render(const LoadedScene& scene, const MethodSettings& settings) override;
    std::string servedBy() const override { return backend_; }  // "egl" or "osmesa"
    // Lights inside an object or within a sample spacing of its boundary, and
    // Gaussians far wider or narrower than their spacing (docs/accuracy.md, Extremes).
    std::vector<std::string> limitations(const LoadedScene& scene) const override;

private:
    std::string backend_;
};

}  // namespace lucent
