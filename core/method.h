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
#include "core/method_options.h"
#include "core/peers.h"

namespace lucent {

// The sample methods' Gaussian cut-off: each Gaussian is drawn where it exceeds
// this fraction of its peak, its kept mass scaled to the whole. Measured
// (docs/accuracy.md, The Gaussian cut-off): 1e-2 keeps the errors of 1e-4
// within 0.02 points (sphere, bunny, CGAL's elephant) in 66-84% of the frame;
// 3e-2 moves them by up to 0.03 points, 0.1 by up to 0.3.
inline constexpr double kDefaultGaussianCutoff = 1e-2;

// The rows of the image one process of several renders (lucent render under
// mpirun, docs/mpi.md): bands of kRows rows dealt round-robin, so that each
// rank gets a share of every part of the frame. A method that honours it
// (splitsRows) leaves the other rows 0, and the ranks' images sum to the whole;
// its pixels are seeded by their position, so the sum does not depend on ranks.
struct RowShare {
    static constexpr int kRows = 8;
    int rank = 0, ranks = 1;
    bool owns(int row) const { return (row / kRows) % ranks == rank; }
};

// What every method shares. What only some methods take (paths per pixel, the
// grid, the OpenGL backend) each method declares as its options (MethodEntry::
// options, core/method_options.h) and reads when it is created.
struct MethodSettings {
    bool surface = true;  // add the reflected surface term of objects that have one
    int threads = 0;      // worker threads of the CPU work (0: all cores)
    uint64_t seed = 1;    // random numbers: the same seed gives the same image
    double cutoff =
        kDefaultGaussianCutoff;  // sample methods: a Gaussian is drawn where it exceeds this fraction of its peak
    RowShare rows;               // the rows to render, by the methods that split rows (MethodEntry::splitsRows)
    // The ranks of an MPI job, to the methods that share their work among them
    // (MethodEntry::sharesSweeps); only rank 0's image is whole.
    const Peers* peers = nullptr;
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

// One row of the method table.
struct MethodEntry {
    std::string name;           // what --method takes
    std::string summary;        // one line for --help and docs
    bool needsSamples = false;  // reads the objects' sample files (lucent preprocess first)
    bool interactive = false;   // fast enough for the viewer and for auto
    // Why the method cannot run here (no device, no driver), or empty when it can.
    std::function<std::string()> unavailableReason;
    std::vector<OptionSpec> options;  // what only this method takes, declared by its class
    // The method with its options read: MethodOptions(options) with what the caller set.
    std::function<std::unique_ptr<Method>(const MethodOptions&)> create;
    bool splitsRows = false;  // honours MethodSettings::rows: ranks under mpirun share its image
    // Under mpirun every rank renders with MethodSettings::peers, sharing the
    // solve (mdom's sweeps); rank 0's image is the frame.
    bool sharesSweeps = false;
    // The method with every option at its default.
    std::unique_ptr<Method> createDefault() const { return create(MethodOptions(options)); }
};

}  // namespace lucent
