#pragma once
// The marching pass on the device (photon_march.cl): the rays of the ray maps,
// the material volume, and two fixed-point deposit volumes so that one can be
// transferred to the lattice while rays march into the other (thesis fig. 4.1).
#include <vector>

#include "core/math.h"
#include "hybrid/internal/cl_device.h"
#include "hybrid/photon_rays.h"
#include "hybrid/voxelisation.h"

namespace lucent::hybrid {

// Power per channel, W.
struct MarchTallies {
    Rgb absorbed{0.0}, escaped{0.0};
};

class PhotonMarcher {
public:
    // step: marching step in world units.
    PhotonMarcher(const ClDevice& device, const cl::Program& program, const Voxelisation& grid, const Rgb& albedo,
                  const RayMap& rays, double step);

    // Marches every live ray `steps` steps, depositing into deposit volume `which` (0 or 1).
    void enqueueMarch(cl::CommandQueue& queue, int steps, int which, std::vector<cl::Event>* after = nullptr,
                      cl::Event* done = nullptr);
    // Adds deposit volume `which` to source (float4 per voxel, W) and clears it.
    void enqueueTransfer(cl::CommandQueue& queue, int which, cl::Buffer& source,
                         std::vector<cl::Event>* after = nullptr, cl::Event* done = nullptr);

    MarchTallies tallies(cl::CommandQueue& queue);
    // Rays still marching after the last launch (read once it has finished).
    size_t marching(cl::CommandQueue& queue);
    std::vector<clshared::PhotonRay> rays(cl::CommandQueue& queue);
    Rgb deposited(cl::CommandQueue& queue, int which);  // sum of a deposit volume, W
    const Rgb& emitted() const { return emitted_; }
    size_t rayCount() const { return rayCount_; }

private:
    cl::Kernel march_, transfer_;
    cl::Buffer rays_, material_, refraction_, deposit_[2], tallies_;
    size_t rayCount_, voxels_;
    Rgb emitted_, unitsPerWatt_;
};

}  // namespace lucent::hybrid
