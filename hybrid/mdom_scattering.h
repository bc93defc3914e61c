#pragma once
// The modified discrete ordinates method of thesis chapter 5 for one object:
// the light reaching each voxel straight from the lights (the direct
// component, thesis 5.2) scatters into a source of a few spherical-harmonic
// moments; sweeps along N directions carry it on, one scattering generation per
// iteration (5.3); the product is the grid of light scattered twice or more
// that the runtime's view pass adds to single scattering, as for LBL.
// Anisotropic media are handled by the delta-M truncation of Henyey-Greenstein
// (docs/hybrid.md). Runs on OpenCL; nothing here touches OpenGL.
#include <array>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "core/peers.h"
#include "core/scattering_grid.h"
#include "core/scene.h"
#include "core/volume_object.h"

namespace lucent::hybrid {

struct MdomSettings {
    int resolution = 64;      // voxels along the longest side of the object's box
    int directions = 48;      // N propagation directions: 24, 48, 80, 120 or 168
    int bands = 4;            // spherical-harmonic bands of the stored source (M = bands^2 moments)
    double tolerance = 1e-2;  // stop when the generations still to come are below this share of the light
    int maxIterations = 200;  // scattering iterations at most
    // The share of the sweeps' volumes the device holds at once (thesis 5.2.2):
    // above 0 they live in host memory in blocks of 32^3 voxels, streamed
    // through a device pool of this share of them (one block at least); 0 keeps
    // the whole grid on the device.
    double devicePool = 0.0;
    // The ranks of an MPI job to share the sweeps with (KBA, hybrid/internal/
    // sweep_halo.h): each rank sweeps its column of voxels, and rank 0 gathers
    // the solution (the others' solutions have no moments). A failure on any
    // rank before the ranks talk ends every rank's solve (PeerFailed on all
    // but the one that says why); one during the sweeps ends the job.
    const Peers* peers = nullptr;
};

// The solution for one object. Per voxel: the moments T_lm = int L Y_lm of
// the light scattered at least once in the delta-M scaled problem, and, per
// light, the excess E* - E of the scaled direct light over the true one: the
// forward peak of delta-M, light scattered once or more that went on along the
// light's direction. The light a voxel scatters towards direction w is
//   sigma_s sum_l g^l sum_m T_lm Y_lm(w) + sigma_s sum_lights (E* - E) p_HG(w_light . w)
// (Henyey-Greenstein is diagonal in l; the peak's direction is known exactly),
// so towards a pinhole camera the view pass's source is a function of the
// voxel alone: towards(eye) bakes it into the runtime's grid.
struct MdomSolution {
    Bounds3 bounds;
    std::array<int, 3> dims{0, 0, 0};
    int bands = 0;
    double g = 0;
    std::vector<glm::vec4> moments;     // [voxel][bands^2], rgb
    std::vector<glm::vec4> scattering;  // sigma_s per voxel (true, not scaled), rgb
    std::vector<glm::vec4> extinction;  // sigma_t per voxel (true), rgb
    struct Peak {
        Light light;
        std::vector<glm::vec4> excess;  // E* - E per voxel, rgb
        // Per voxel, the direction the light travels there, refracted by the
        // boundary; empty when it comes straight from the light.
        std::vector<glm::vec3> travel;
        Vec3 travelAt(size_t voxel, const Vec3& centre) const {
            if (!travel.empty()) return Vec3(travel[voxel]);
            return light.type == Light::Type::Point ? centre - light.position : light.direction;
        }
    };
    std::vector<Peak> peaks;
    // Where the medium refracts: the smoothed index and its gradient per voxel,
    // as ScatteringGrid::refraction (Voxelisation::viewRefraction); else empty.
    std::vector<float> refraction;
    double ior = 1.0;

    // The view pass's grid for a pinhole camera at eye. The light scattered
    // towards the eye is evaluated for the straight direction to it, also
    // where the view bends.
    ScatteringGrid towards(const Vec3& eye) const;
};

struct MdomStats {
    std::string device;
    double voxeliseSeconds = 0, directSeconds = 0, sweepSeconds = 0;
    int iterations = 0;
    bool converged = false;
    Rgb ratio{0.0};                                 // of the last two generations' light
    int poolSlots = 1, poolBlocks = 1;              // blocks the device holds at once, of all
    double bytesToDevice = 0, bytesFromDevice = 0;  // the pool's copies
    bool spilled = false;                           // the host's blocks in a file (TMPDIR)
};

class MdomScattering;

// One object's solve, an iteration at a time (the viewer shows each one). Made
// by MdomScattering::begin, which must outlive it.
class MdomProgress {
public:
    ~MdomProgress();
    // One more scattering iteration; false once converged or at the limit.
    bool iterate();
    // The generations so far (reads the device).
    MdomSolution solution() const;
    const MdomStats& stats() const;

private:
    friend class MdomScattering;
    struct Impl;
    explicit MdomProgress(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> impl_;
};

class MdomScattering {
public:
    // Opens the OpenCL device; Error when there is none.
    MdomScattering();
    ~MdomScattering();
    MdomScattering(const MdomScattering&) = delete;
    MdomScattering& operator=(const MdomScattering&) = delete;

    std::string deviceName() const;
    // Device memory a solve on a grid of these dimensions takes.
    static size_t bytesFor(const std::array<int, 3>& dims, int directions, int bands, double devicePool = 0.0);
    // Host memory the blocks of a device pool take (0 without one), for an
    // object whose boundary refracts or not.
    static size_t poolHostBytes(const std::array<int, 3>& dims, int bands, double devicePool, bool refracts);

    // afterIteration(i, solution): the solution with the generations so far
    // (thesis 5.3.3: each iteration's image is available); called only when
    // given, as it reads the device.
    using IterationCallback = std::function<void(int, const MdomSolution&)>;
    std::unique_ptr<MdomProgress> begin(const VolumeObject& object, const std::vector<Light>& lights,
                                        const MdomSettings& settings);
    MdomSolution solve(const VolumeObject& object, const std::vector<Light>& lights, const MdomSettings& settings,
                       MdomStats* stats = nullptr, const IterationCallback& afterIteration = {});

private:
    // begin() on this rank alone, before any agreement with the others.
    std::unique_ptr<MdomProgress> prepare(const VolumeObject& object, const std::vector<Light>& lights,
                                          const MdomSettings& settings);
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace lucent::hybrid
