#pragma once
// --method path: the PathTracer behind the method interface.
#include "core/method.h"
#include "reference/path_tracer.h"

namespace lucent {

// Objects whose boxes overlap in a scene with a refracting boundary: method
// (the path tracer, the reference) takes each boundary to separate one medium
// from the air there, and is wrong where objects overlap.
std::vector<std::string> overlappingRefractors(const LoadedScene& scene, const std::string& method);

class PathMethod final : public Method {
public:
    // paths: samples, noise and max-scatter are read; the rest comes from MethodSettings.
    explicit PathMethod(PathSettings paths = {}) : paths_(paths) {}
    // --samples, --noise, --max-scatter.
    static std::vector<OptionSpec> options();
    static std::unique_ptr<Method> create(const MethodOptions& options);
    Image render(const LoadedScene& scene, const MethodSettings& settings) override;
    // Objects whose boxes overlap in a scene with a refracting boundary (each
    // boundary must separate one medium from the air there).
    std::vector<std::string> limitations(const LoadedScene& scene, const MethodSettings& settings) const override;

private:
    PathSettings paths_;
};

}  // namespace lucent
