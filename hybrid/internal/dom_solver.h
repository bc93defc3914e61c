#pragma once
// The discrete ordinates solver on the device (dom_sweep.cl): a box of voxels
// with per-voxel scaled extinction, scattering and phase moments, swept along
// N directions octant by octant, one scattering generation per iteration
// (thesis 5.3.3: the G'' of an iteration is this generation's source, G' the
// next one's, G the total). Used by the renderer's mdom method and by
// `lucent transport`; knows nothing of meshes or lights.
#include <array>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "core/grid_index.h"
#include "core/math.h"
#include "hybrid/internal/block_pool.h"
#include "hybrid/internal/cl_device.h"
#include "hybrid/ordinates.h"

namespace lucent::hybrid {

class SweepHalo;

struct DomGrid {
    std::array<int, 3> dims{0, 0, 0};
    Vec3 edges{1.0};                    // a voxel's edge lengths
    std::vector<glm::vec4> extinction;  // sigma_t* (delta-M scaled), rgb; a: 1 where the flux is wanted, else 0
                                        // (a voxel with a = 0 must have no source)
    std::vector<glm::vec4> scattering;  // sigma_s*, rgb
    std::vector<glm::vec4> phase;       // x: Henyey-Greenstein g (truncated by delta-M to the bands stored)
    // The medium's refractive index: other than 1, the faces between a voxel
    // whose flux is wanted and one of air (extinction 0) reflect inside by
    // Fresnel, at the angle to the boundary's outward unit normal there
    // (per voxel, the mean of the face's two voxels is taken).
    double ior = 1.0;
    std::vector<glm::vec3> boundaryNormal;
    // A share of a larger grid (an MPI rank's) is given its inner boundary as
    // DomSolver::innerBoundary finds it on the whole grid, cut to the share,
    // so that faces on the share's border are kept; empty: found in this grid.
    std::vector<cl_int> innerFace;      // [voxel][6]
    std::vector<glm::vec3> faceNormal;  // [face]
    size_t count() const { return index().count(); }
    GridIndex index() const { return {dims}; }
};

// Faces of the box, in the order of the boundary flags: x-, x+, y-, y+, z-, z+.
using BoundaryFlags = std::array<bool, 6>;

// Where the solver's volumes live (block_pool.h). share 0: the whole grid on
// the device, as one block. Above 0: in blocks of edge^3 voxels in host
// memory, of which the device holds this share at once (one block at least).
// A share that holds every block needs no blocks: the whole grid is one.
struct DomPool {
    DomPool(double share = 0.0, int edge = 32, std::filesystem::path spillTo = {})
        : share(share), edge(edge), spillTo(std::move(spillTo)) {}
    double share;
    int edge;
    std::filesystem::path spillTo;  // a directory for the host's blocks (host_blocks.h); empty: memory
};

class DomSolver {
public:
    static constexpr int kMaxBands = 6;
    // bands: spherical-harmonic bands stored (1 to kMaxBands: M = bands^2 moments).
    // reflective: faces that mirror the light leaving them back in (with one
    // iteration's delay); the others are vacuum, or a neighbour's when halo
    // (owned by the caller, outliving the solver) shares the sweeps with the
    // ranks of an MPI job: the grid is then this rank's share.
    // A pool that cuts the grid into blocks takes neither reflective faces nor a halo.
    DomSolver(const ClDevice& device, const DomGrid& grid, int directions, int bands, const BoundaryFlags& reflective,
              SweepHalo* halo = nullptr, const DomPool& pool = {});
    ~DomSolver();

    int moments() const { return moments_; }
    const Ordinates& ordinates() const { return ordinates_; }
    // Device memory for a grid of `voxels` (and the neighbours' radiance when
    // shared) and the largest single buffer; with a pool, the host's copies of
    // the blocks (hostBytesFor; 0 without).
    static size_t bytesFor(const std::array<int, 3>& dims, int directions, int bands, bool shared = false,
                           const DomPool& pool = {});
    static size_t largestBufferFor(const std::array<int, 3>& dims, int bands, const DomPool& pool = {});
    // `refracts`: the object's boundary reflects (ior other than 1), so the
    // blocks keep its inner faces too.
    static size_t hostBytesFor(const std::array<int, 3>& dims, int bands, const DomPool& pool, bool refracts);
    // Whether the pool cuts the grid into blocks, and how many the device holds (1 without).
    static bool pooled(const std::array<int, 3>& dims, const DomPool& pool);
    static int slotsFor(const std::array<int, 3>& dims, const DomPool& pool);
    // Whether the host's blocks went to a file.
    bool spilled() const { return pool_->spilled(); }
    // The faces of the inner boundary: [voxel][6], each voxel's faces to -x,
    // +x, -y, +y, -z and +z, numbered where one side's flux is wanted and the
    // other is air, else -1; and each face's normal, the boundary's outward
    // unit normal there (the mean of its two voxels').
    struct InnerBoundary {
        std::vector<cl_int> faces;
        std::vector<glm::vec3> normals;
    };
    static InnerBoundary innerBoundary(const DomGrid& grid);
    // What the pool copied (zero without one).
    const BlockPool::Traffic& traffic() const;

    // The first generation's radiance source, [voxel][M] moments (rgb) per unit length.
    void setSource(cl::CommandQueue& queue, const std::vector<glm::vec4>& source);
    // Instead of a source: the uncollided flux moments, [voxel][M] (rgb),
    // computed outside the sweeps (the first-collision source method). They
    // join the total as generation zero and scatter into the first source, so
    // that the sweeps carry only light that has collided.
    // With `sources`, the sources' moments as setSource takes them, the light
    // that collides where the sources are is taken out of the sweeps too (a
    // first-collided source): in every generation, c times the sources, c
    // such that it holds all the scattering source's zero moment in the source
    // voxels, is no longer swept, and its flux is c times `flux`. The sweeps
    // carry only what differs from the sources' shape there. Not pooled.
    void setUncollidedFlux(cl::CommandQueue& queue, const std::vector<glm::vec4>& flux,
                           const std::vector<glm::vec4>& sources = {});
    // One iteration: eight octant sweeps of the current source, the generation's
    // flux added to the total and scattered into the next source. Returns the
    // generation's summed zero moments per channel (how much light it carried).
    Rgb iterate(cl::CommandQueue& queue);
    // Adds factor[c] times the last generation's flux to the total (the
    // geometric tail of the generations still to come).
    void addTail(cl::CommandQueue& queue, const Rgb& factor);
    // Iterates until, in every channel, the generations' estimated remaining
    // light, the geometric tail last r / (1 - r) with r the ratio of the last
    // two generations, is below `tolerance` of the total, or r has settled to
    // within tolerance (1 - r) so that the tail is known to about tolerance;
    // then the tail is added. At most maxIterations. afterEach(iteration) runs
    // after each one.
    struct Run {
        int iterations = 0;
        bool converged = false;
        Rgb ratio{0.0};  // of the last two generations
    };
    Run run(cl::CommandQueue& queue, double tolerance, int maxIterations,
            const std::function<void(int)>& afterEach = {});
    // The same one iteration at a time (for a viewer that shows each one):
    // false once converged, the tail added.
    bool step(cl::CommandQueue& queue, double tolerance);
    const Run& progress() const { return run_; }
    // The total flux moments phi_m = sum_n w_n L_n Y_m(omega_n), [voxel][M] (rgb).
    std::vector<glm::vec4> totalFlux(cl::CommandQueue& queue);
    // The out-going radiance (rgb) of the last iteration on every face, [face cells][N]
    // face by face (x-, x+, y-, y+, z-, z+).
    std::vector<glm::vec4> boundaryRadiance(cl::CommandQueue& queue);
    // Where face 0-5's cells start in the boundary radiance; face 6 gives the total.
    static size_t faceOffset(int face, const std::array<int, 3>& dims, int directions);

private:
    // The volumes each block keeps.
    enum Volume { kExtinction, kScattering, kPhase, kInnerFace, kSource, kFlux, kLastFlux, kTotal };
    static std::vector<size_t> volumeBytes(int bands, bool mirrors);
    // The grid's values of a volume (grid order, perCell values per voxel),
    // block by block into the pool.
    template <typename T>
    void setVolume(const cl::CommandQueue& queue, Volume volume, const std::vector<T>& values, size_t perCell);
    // One octant's sweep of block b.
    void sweepBlock(cl::CommandQueue& queue, int octant, int b);
    // The radiance the blocks upstream left by the faces block b enters by,
    // into haloIn_; and what block b leaves by its faces towards blocks downstream.
    void receiveFaces(cl::CommandQueue& queue, int octant, int b);
    void keepFaces(cl::CommandQueue& queue, int octant, int b);
    // The generation in the flux volume joins the total and scatters into the
    // next source; it becomes the last flux, and the flux is cleared. Returns
    // the generation's summed zero moments (this rank's).
    Rgb scatterGeneration(cl::CommandQueue& queue);
    // The first-collided source's share of this generation's source: taken
    // out of it, its flux put in the flux volume before the sweeps add theirs.
    void takeSourcesShape(cl::CommandQueue& queue);

    DomGrid grid_;
    Ordinates ordinates_;
    int moments_;
    int reflectiveMask_ = 0;
    int swaps_ = 0;
    Run run_;
    Rgb total_power_{0.0}, previous_power_{0.0};
    std::optional<Rgb> uncollidedPower_;  // this rank's, until the first step sums it over the ranks
    cl::Program program_;
    cl::Kernel sweep_, scatter_, power_, add_, gatherZero_, takeShape_;
    // The first-collided source: the source voxels, the sources' zero moments
    // there and their sum (over the ranks), and the uncollided flux.
    struct SourcesShape {
        size_t voxels = 0;
        Rgb total{0.0};
        bool summed = false;
        cl::Buffer at, shape, gathered, flux;
    };
    std::optional<SourcesShape> sourcesShape_;
    BlockTiling tiling_;
    std::unique_ptr<BlockPool> pool_;
    std::array<std::vector<std::vector<int>>, 8> order_;  // per octant, the block wavefronts
    // Per block and axis, the radiance it left by its downstream face in this octant ([cell][K]).
    std::vector<std::vector<glm::vec4>> leaving_;
    cl::Buffer yFace_, zFace_, boundary_[2], ylm_, weights_, crossing_, partial_;
    // The object's inner boundary (dom_sweep.cl): what each face reflected.
    cl::Buffer mirror_[2], fresnel_;  // fresnel_: [face][N], R of each direction leaving by it
    bool mirrors_ = false;
    SweepHalo* halo_ = nullptr;
    cl::Buffer haloIn_;  // the radiance the neighbours sent, laid out as the boundary buffers
};

}  // namespace lucent::hybrid
