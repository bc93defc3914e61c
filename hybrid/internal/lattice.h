#pragma once
// The diffusion pass on the device (lattice.cl): the Lattice-Boltzmann state of
// every voxel, its tallies, and either the blocked lattice (4^3 blocks with
// interface buffers, thesis 4.5) or the global one (one step over all voxels).
#include <vector>

#include <glm/glm.hpp>

#include "core/math.h"
#include "core/scattering_grid.h"
#include "hybrid/internal/cl_device.h"
#include "hybrid/voxelisation.h"

namespace lucent::hybrid {

// Power per channel, W (absorbed and escaped: summed over all steps so far).
struct LatticeTotals {
    Rgb inFlight{0.0}, absorbed{0.0}, escaped{0.0};
};

double latticeBoundaryReflectance(double ior);

class Lattice {
public:
    // subSteps: lattice steps per launch of the blocked lattice (ignored by the global one).
    // With g != 0 the lattice, whose scattering is isotropic, runs on the reduced
    // coefficients of the similarity relation, sigma'_s = (1 - g) sigma_s, which
    // keep the diffusion coefficient 1 / (3 (sigma_a + sigma'_s)) of the medium.
    Lattice(const ClDevice& device, const cl::Program& program, const Voxelisation& grid, const Rgb& albedo,
            bool blocked, int subSteps, double g = 0.0);

    // Power waiting to be emitted isotropically at the next step (float4 per voxel, W).
    cl::Buffer& source() { return source_; }
    // One launch: subSteps steps (blocked) or one step (global).
    void enqueueLaunch(cl::CommandQueue& queue, std::vector<cl::Event>* after = nullptr, cl::Event* done = nullptr);
    int stepsPerLaunch() const { return blocked_ ? subSteps_ : 1; }

    // The fluence tally summed over the probe voxels (thesis 4.6.1), per channel.
    Rgb probeSum(cl::CommandQueue& queue);
    // Voxels with medium, spread over the grid, at most `count`.
    void chooseProbes(int count);

    std::vector<glm::vec4> fluenceTally(cl::CommandQueue& queue);  // sum over steps of the arriving power
    LatticeTotals totals(cl::CommandQueue& queue);
    // sigma_s phi / (4 pi) and sigma_t per voxel, for the view pass.
    ScatteringGrid finish(cl::CommandQueue& queue);

    // Total device memory the lattice of `voxels` takes, and its largest buffer.
    static size_t bytesFor(size_t voxels, bool blocked);
    static size_t largestBufferFor(size_t voxels) { return voxels * 6 * sizeof(glm::vec4); }

private:
    std::vector<glm::vec4> read(cl::CommandQueue& queue, cl::Buffer& buffer, size_t count);

    const Voxelisation& grid_;
    Rgb albedo_;                  // of the medium: what finish scatters towards the eye
    Rgb latticeExtinctionScale_;  // sigma'_t / sigma_t = 1 - albedo g
    cl::Buffer trueMaterial_;     // sigma_t as the medium has it (material_ holds sigma'_t)
    bool blocked_;
    int subSteps_;
    size_t voxels_;
    cl::Kernel collide_, stream_, blocks_, probes_, finish_;
    cl::Buffer f_, out_, source_, material_, fluence_, absorbed_, escaped_, interface_[2], active_, blockActive_,
        probeIndex_, probeOut_;
    int activeCount_ = 0, launches_ = 0, probeCount_ = 0;
};

}  // namespace lucent::hybrid
