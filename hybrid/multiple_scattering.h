#pragma once
// The hybrid of thesis chapter 4 for one object: photon marching from the
// lights through the voxelised object deposits the power each voxel scatters
// once; the Lattice-Boltzmann lattice carries it on through further scattering
// until it is absorbed or leaves; the product is the grid of light scattered
// twice or more that the runtime's view pass adds to single scattering.
// Runs on OpenCL (PoCL on a CPU); nothing here touches OpenGL.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/scattering_grid.h"
#include "core/scene.h"
#include "core/volume_object.h"

namespace lucent::hybrid {

struct HybridSettings {
    int resolution = 64;      // voxels along the longest side of the object's box
    int raysPerLight = 0;     // photon rays per light (0: 4 per voxel of a grid face, 4 resolution^2)
    int marchSteps = 16;      // k: steps a ray marches per launch, the ray history size (thesis 4.7.3)
    double stepVoxels = 0.5;  // marching step in voxels
    int subSteps = 4;         // lattice steps per launch of a block
    double tolerance = 1e-3;  // stop when the probes' estimated remaining change is below this share
    int probes = 64;          // voxels watched for convergence (thesis 4.6.1)
    bool concurrent = true;   // march step i+1 while step i diffuses (thesis fig. 4.1)
    bool blocked = true;      // 4^3 blocks with interfaces (thesis 4.5); false: the global lattice
    int maxLatticeSteps = 1000000;
    uint64_t seed = 1;
};

struct HybridStats {
    std::string device;
    double voxeliseSeconds = 0, solveSeconds = 0;
    double marchSeconds = 0;  // marching with its atomic deposits alone (measured when not concurrent)
    int iterations = 0, latticeSteps = 0, marchLaunches = 0;
    bool converged = false;
    size_t rays = 0;
    Rgb emitted{0.0};                           // by the ray maps into the grid
    Rgb marchAbsorbed{0.0}, marchEscaped{0.0};  // along the rays
    Rgb injected{0.0};                          // scattered once: what the lattice received
    Rgb latticeAbsorbed{0.0}, latticeEscaped{0.0}, latticeInFlight{0.0};
};

class MultipleScattering {
public:
    // Opens the OpenCL device and builds the kernels; Error when either fails.
    MultipleScattering();
    ~MultipleScattering();
    MultipleScattering(const MultipleScattering&) = delete;
    MultipleScattering& operator=(const MultipleScattering&) = delete;

    // Why the hybrid cannot run here (no OpenCL device), or empty.
    static std::string unavailableReason();
    std::string deviceName() const;

    ScatteringGrid solve(const VolumeObject& object, const std::vector<Light>& lights, const HybridSettings& settings,
                         HybridStats* stats = nullptr);

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace lucent::hybrid
