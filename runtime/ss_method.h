#pragma once
// --method ss: the scene's objects with their sample sets, drawn offscreen by the
// ScatteringRenderer through EGL or OSMesa.
#include "core/method.h"
#include "core/scattering_grid.h"

namespace lucent {

// The options of ss, which lbl and mdom take too since they draw its frame.
struct SsOptions {
    bool tracedLight = true;  // each sample's light traced, not read from its SH (DrawOptions::tracedLight)
    std::string backend;      // "egl", "osmesa" or "" (EGL, then OSMesa)
    // An environment light is drawn as this many directional lights, drawn from its map
    // (EnvironmentMap::asDirectionalLights); lbl and mdom solve their grids for up to 16
    // of them. 32: under a sky with a sun as close to the reference as 64 or 128, at
    // half 64's time; 16 were twice as far (docs/results/environment.md).
    int environmentLights = 32;
    // --light, --backend and --env-lights.
    static std::vector<OptionSpec> specs();
    static SsOptions from(const MethodOptions& options);
};

class SsMethod final : public Method {
public:
    explicit SsMethod(SsOptions options = {});
    static std::unique_ptr<Method> create(const MethodOptions& options);
    ~SsMethod() override;
    // The OpenGL context, the frame and the renderer with its programs, made in
    // a thread of their own while the scene loads; render() makes the context
    // current in its thread.
    void prepare(const SceneDesc& desc, const MethodSettings& settings) override;
    Image render(const LoadedScene& scene, const MethodSettings& settings) override;
    std::string servedBy() const override { return backend_; }  // "egl" or "osmesa"
    // boundaryLimitations and sampleLimitations.
    std::vector<std::string> limitations(const LoadedScene& scene, const MethodSettings& settings) const override;
    // Boundaries that refract (ior != 1) but are drawn index-matched (the light
    // from the SH, a density that varies, an optically thick object), and the
    // views a refracting one is not drawn in.
    static std::vector<std::string> boundaryLimitations(const LoadedScene& scene, const SsOptions& options);
    // Lights inside an object or within a sample spacing of its boundary, other
    // objects in a light's way, and Gaussians far wider or narrower than their
    // spacing (docs/accuracy.md, Extremes): what every method drawing the samples shares.
    static std::vector<std::string> sampleLimitations(const LoadedScene& scene, const SsOptions& options);

private:
    SsOptions options_;
    std::string backend_;
    struct Prepared;
    std::unique_ptr<Prepared> prepared_;
    struct Retiring;  // the last render's session, being torn down
    std::unique_ptr<Retiring> retiring_;
};

// The frame --method ss draws, plus grids of multiple scattering (--method lbl
// adds its own); backend receives "egl" or "osmesa".
Image renderSingleScattering(const LoadedScene& scene, const MethodSettings& settings, const SsOptions& options,
                             const std::vector<ScatteringGrid>& grids, std::string& backend);

class ScatteringRenderer;

// Gives renderer the scene's lights and environment as --method ss draws them.
// The environment's options.environmentLights directions are lights like any
// other when the light is traced; read from the SH (--light sh) they are
// projected once onto SH (ScatteringRenderer::setEnvironment), in media whose g
// the bands hold (environmentShHolds), and are lights again otherwise.
void setSsLights(ScatteringRenderer& renderer, const LoadedScene& scene, const SsOptions& options);

}  // namespace lucent
