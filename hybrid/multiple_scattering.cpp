#include "hybrid/multiple_scattering.h"

#include <cmath>

#include "core/error.h"
#include "core/stopwatch.h"
#include "hybrid/internal/cl_device.h"
#include "hybrid/internal/lattice.h"
#include "hybrid/internal/photon_marcher.h"
#include "hybrid/photon_rays.h"
#include "hybrid/voxelisation.h"

namespace lucent::hybrid {

struct MultipleScattering::Impl {
    ClDevice device;
    cl::Program program = device.build({"photon_march.cl", "lattice.cl"});
};

MultipleScattering::MultipleScattering() : impl_(std::make_unique<Impl>()) {}
MultipleScattering::~MultipleScattering() = default;

std::string MultipleScattering::unavailableReason() { return ClDevice::unavailableReason(); }
std::string MultipleScattering::deviceName() const { return impl_->device.name(); }

namespace {

double maxOf(const Rgb& c) { return std::max({c.r, c.g, c.b}); }

}  // namespace

ScatteringGrid MultipleScattering::solve(const VolumeObject& object, const std::vector<Light>& lights,
                                         const HybridSettings& s, HybridStats* statsOut) {
    HybridStats stats;
    ClDevice& device = impl_->device;
    stats.device = device.name();
    Stopwatch stopwatch;
    const GridShape shape = gridShapeFor(object.mesh().bounds(), s.resolution);
    const std::string what = shape.describe(object.desc().name);
    const size_t voxels = shape.count();
    // Marching: material, refraction, two fixed-point deposits; lattice; rays are small.
    device.checkMemory(voxels * (2 * 16 + 2 * 24) + Lattice::bytesFor(voxels, s.blocked),
                       Lattice::largestBufferFor(voxels), what);
    const Voxelisation grid = voxelise(object, s.resolution);
    stats.voxeliseSeconds = stopwatch.seconds();
    stopwatch.restart();

    const Rgb albedo = object.desc().medium.albedo;
    const int raysPerLight = s.raysPerLight > 0 ? s.raysPerLight : 4 * s.resolution * s.resolution;
    const RayMap rays = rayMapFor(lights, shape, raysPerLight, s.seed);
    stats.rays = rays.rays.size();
    stats.emitted = rays.emitted;
    const double step = s.stepVoxels * shape.voxel;
    // A ray crosses the grid's diagonal in this many steps; more means it is caught
    // bending in circles (total internal reflection in a smoothed index): stopped.
    const int maxMarchSteps =
        int(std::ceil(4.0 *
                      std::sqrt(double(shape.dims[0] * shape.dims[0] + shape.dims[1] * shape.dims[1] +
                                       shape.dims[2] * shape.dims[2])) /
                      s.stepVoxels));

    try {
        PhotonMarcher marcher(device, impl_->program, grid, albedo, rays, step);
        Lattice lattice(device, impl_->program, grid, albedo, s.blocked, s.subSteps, object.desc().medium.g);
        lattice.chooseProbes(s.probes);
        cl::CommandQueue& mq = device.marchQueue;
        cl::CommandQueue& lq = device.latticeQueue;

        // Iteration i: rays march k steps into deposit volume i % 2 while the
        // lattice takes in volume (i - 1) % 2 and diffuses (thesis fig. 4.1).
        int marched = 0, sinceMarching = 0;
        bool marchedInto[2] = {false, false};  // deposit volumes waiting for their transfer
        constexpr int kProbeEvery = 4;
        bool raysLeft = !rays.rays.empty();
        Rgb previous(0.0), lastChange(0.0);
        bool haveChange = false;
        for (int i = 0;; ++i) {
            const bool marching = raysLeft && marched < maxMarchSteps;
            if (marching) {
                const Stopwatch march;
                marcher.enqueueMarch(mq, s.marchSteps, i % 2);
                marchedInto[i % 2] = true;
                marched += s.marchSteps;
                ++stats.marchLaunches;
                if (!s.concurrent) {
                    mq.finish();
                    stats.marchSeconds += march.seconds();
                }
            }
            if (i > 0) {
                if (marchedInto[(i - 1) % 2]) marcher.enqueueTransfer(lq, (i - 1) % 2, lattice.source());
                marchedInto[(i - 1) % 2] = false;
                lattice.enqueueLaunch(lq);
                stats.latticeSteps += lattice.stepsPerLaunch();
            }
            mq.finish();
            lq.finish();
            if (marching) raysLeft = marcher.marching(mq) > 0;
            ++stats.iterations;
            if (marching || i == 0) continue;
            // Marching is over and its last deposit transferred: watch the probes,
            // every kProbeEvery iterations (reading them back costs a launch and a wait).
            if (++sinceMarching % kProbeEvery != 0 && stats.latticeSteps < s.maxLatticeSteps) continue;
            const Rgb sum = lattice.probeSum(lq);
            const Rgb change = sum - previous;
            previous = sum;
            if (maxOf(sum) <= 0.0 && i > 2) {  // no light reached the medium, or none stays
                stats.converged = true;
                break;
            }
            // The probes' tally grows geometrically once the source has died out:
            // with r = change / previous change, what is still to come is change r / (1 - r).
            bool done = haveChange;
            for (int c = 0; c < 3 && done; ++c) {
                // A channel whose probes saw nothing more arrive is done (its light has
                // died out below the tally's float precision).
                if (sum[c] <= 0.0 || change[c] <= 0.0) continue;
                const double r = lastChange[c] > 0.0 ? std::min(change[c] / lastChange[c], 0.999999) : 0.999999;
                done = change[c] * r / (1.0 - r) <= s.tolerance * sum[c];
            }
            lastChange = change;
            haveChange = true;
            if (done) {
                stats.converged = true;
                break;
            }
            if (stats.latticeSteps >= s.maxLatticeSteps) break;
        }
        const MarchTallies mt = marcher.tallies(mq);
        stats.marchAbsorbed = mt.absorbed;
        stats.marchEscaped = mt.escaped;
        const LatticeTotals lt = lattice.totals(lq);
        stats.latticeAbsorbed = lt.absorbed;
        stats.latticeEscaped = lt.escaped;
        stats.latticeInFlight = lt.inFlight;
        stats.injected = lt.absorbed + lt.escaped + lt.inFlight;
        ScatteringGrid out = lattice.finish(lq);
        stats.solveSeconds = stopwatch.seconds();
        if (statsOut) *statsOut = stats;
        return out;
    } catch (const cl::Error& e) {
        throw Error("OpenCL device '" + device.name() + "': " + e.what() + " failed for " + what + ": " +
                    clErrorText(e.err()));
    }
}

}  // namespace lucent::hybrid
