#pragma once
// The one interface of every rendering method (pbrt-v4's Integrator, here for a
// whole frame): a loaded scene and settings in, a linear radiance image out.
// Each stage implements it in its own folder (reference/, runtime/, later
// hybrid/); methods/method_table.cpp lists them, with their factories, for the
// command line, the viewer and the benchmarks.
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/image.h"
#include "core/loaded_scene.h"

namespace lucent {

// The sample methods' Gaussian cut-off: each Gaussian is drawn where it exceeds
// this fraction of its peak, its kept mass scaled to the whole. Measured
// (docs/accuracy.md, The Gaussian cut-off): 1e-2 keeps the errors of 1e-4
// within 0.02 points (sphere, bunny, CGAL's elephant) in 66-84% of the frame;
// 3e-2 moves them by up to 0.03 points, 0.1 by up to 0.3.
inline constexpr double kDefaultGaussianCutoff = 1e-2;

// What a caller may ask of any method; each method reads the fields it knows.
struct MethodSettings {
    bool surface = true;      // add the reflected surface term of objects that have one
    int threads = 0;          // CPU methods: worker threads (0: all cores)
    double tolerance = 1e-3;  // quadrature methods: relative error target per pixel
    std::string backend;      // OpenGL methods: "egl", "osmesa" or "" (EGL, then OSMesa)
    double cutoff =
        kDefaultGaussianCutoff;  // sample methods: a Gaussian is drawn where it exceeds this fraction of its peak
    bool tracedLight =
        true;  // sample methods: each sample's light traced, not read from its SH (DrawOptions::tracedLight)
    int samplesPerPixel = 64;  // Monte Carlo methods: paths per pixel
    int maxScatter = 1 << 20;  // Monte Carlo methods: collisions per path (1: single scattering)
    double noiseTarget = 0.0;  // Monte Carlo methods: relative standard error per pixel (0: samplesPerPixel each)
    uint64_t seed = 1;         // Monte Carlo methods: the same seed gives the same image
    int gridResolution = 64;   // grid methods: voxels along each object's longest side
    int directions = 48;       // discrete ordinates: propagation directions (24, 48, 80, 120, 168)
    int moments = 16;          // discrete ordinates: spherical-harmonic moments stored per voxel (4 ... 36)
};

class Method {
public:
    virtual ~Method() = default;
    // Starts what needs only the scene's description, so that it runs while the
    // scene loads (ss: the OpenGL context, the frame and the compiled programs).
    // render() takes it over when given the same
    // description and settings; otherwise it is dropped. Optional for callers.
    virtual void prepare(const SceneDesc&, const MethodSettings&) {}
    // The scene as loadScene gives it, with sample sets when the method's entry
    // says it needs them. Throws Error for what the method cannot do.
    virtual Image render(const LoadedScene& scene, const MethodSettings& settings) = 0;
    // What served the last render, for messages (an OpenGL backend, a device); may be empty.
    virtual std::string servedBy() const { return {}; }
    // What this method is known to get wrong about this scene, one line each
    // (shown as warnings) with these settings: the cases where it misses its accuracy goal.
    virtual std::vector<std::string> limitations(const LoadedScene&, const MethodSettings&) const { return {}; }
};

// One warning per object whose ior differs from 1, for a method that treats
// every boundary as index-matched: no bending, no reflection.
inline std::vector<std::string> indexMatchedWarnings(const LoadedScene& scene, const std::string& method) {
    std::vector<std::string> out;
    for (const VolumeObject& o : scene.objects)
        if (o.desc().medium.ior != 1.0)
            out.push_back("object '" + o.desc().name + "': ior " + std::to_string(o.desc().medium.ior) +
                          " is treated as index-matched by --method " + method +
                          ": no refraction, no reflection at the boundary (--method path refracts)");
    return out;
}

// One row of the method table.
struct MethodEntry {
    std::string name;           // what --method takes
    std::string summary;        // one line for --help and docs
    bool needsSamples = false;  // reads the objects' sample files (lucent preprocess first)
    bool interactive = false;   // fast enough for the viewer and for auto
    // Why the method cannot run here (no device, no driver), or empty when it can.
    std::function<std::string()> unavailableReason;
    std::function<std::unique_ptr<Method>()> create;
};

}  // namespace lucent
