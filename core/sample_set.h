#pragma once
// The preprocessor's product and the runtime's input: Gaussian samples inside
// one object, each carrying the SH projection of its directional attenuation
// exp(-tau(b_i, w)) (thesis 3.3). Stored in the versioned binary sample file of
// DESIGN.md (see docs/sample-file.md for the byte layout).
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <span>
#include <vector>

#include "core/math.h"
#include "core/triangle_mesh.h"

namespace lucent {

// How the Gaussians reconstruct the scattered light (docs/accuracy.md).
// Published: thesis 3.3 as written (layers from one spacing down, FWHM = radius,
// weights by share of volume, the light at the centre held constant over the
// Gaussian). Lucent: the first layer half a spacing down, Galerkin
// partition-of-unity weights restricted to the inside, the Gaussians clipped to
// their density slab, the light varying exponentially across each Gaussian, and
// psi projected with the blockers filled by the medium, their shadows left to
// the runtime (runtime/internal/blocker_shadows.h).
// OpticallyThick: the medium is optically thick at the scale of the samples (light dies
// within a fraction of their spacing), there are none, and the runtime draws the
// single scattering of the surface's sliver in closed form (runtime/internal/optically_thick.frag).
enum class SampleScheme : uint32_t { Lucent = 0, Published = 1, OpticallyThick = 2 };
inline constexpr uint32_t kNoRegionAxis = 3;

struct SampleParameters {
    uint64_t seed = 1;
    uint32_t heuristicDirections = 64;
    uint32_t projectionDirections = 128;
    uint32_t layerCount = 0;
    float layerSpacing = 0.0f;  // scene units between offset layers
    float meanRadius = 0.0f;    // r of thesis 3.2.4
    float widthFactor = 1.0f;   // Gaussian FWHM = widthFactor * Poisson radius (thesis 3.3.2)
    float cullEpsilon = 1e-3f;  // samples receiving less than this fraction of full light are culled
    SampleScheme scheme = SampleScheme::Lucent;
    uint32_t regionAxis = kNoRegionAxis;  // axis of the density slabs the Gaussians are clipped to
    // The placement's scale the object was preprocessed at (its optical size:
    // sigma_t per world unit times this per object unit). The runtime raises
    // psi to placement scale / this (runtime/internal/sample_light.glsl).
    float placementScale = 1.0f;
};

// A ball of the medium tangent to the object's boundary at the point nearest to a
// sample, standing for the object around it: its transmittance is exp(-tau) up to
// the curvature and the density beyond, and it holds the step at the horizon that
// low-order SH cannot (preprocess/sh_projection.h).
struct BoundaryBall {
    glm::vec3 normal{0.0f};  // outward unit normal at the nearest boundary point
    float depth = -1.0f;     // distance of the sample to it; < 0: no ball (the published scheme)
    float curvature = 0.0f;  // 1 / radius, of the boundary there; 0: the half-space under the tangent plane
    float share = 0.0f;      // in [0, 1]: how much of the ball's transmittance psi_i takes
    bool valid() const { return depth >= 0.0f; }
};
static_assert(sizeof(BoundaryBall) == 6 * sizeof(float));

// Where a set read from a file finds its SH coefficients (core/sample_set.cpp).
class CoefficientsInFile;

struct SampleSet {
    uint32_t shOrder = 5;   // bands; shOrder^2 coefficients per channel
    uint32_t channels = 1;  // 1 when sigma_t is grey, 3 when it differs per channel
    uint64_t sceneFingerprint = 0;
    Bounds3 bounds;
    SampleParameters parameters;

    std::vector<glm::vec3> positions;
    std::vector<float> radii;   // Poisson-disk radius
    std::vector<float> widths;  // Gaussian standard deviation: gamma(x) = exp(-|x-b|^2 / (2 w^2))
    // w_i, the partition-of-unity weight: a Gaussian scatters w_i sigma_s(b_i), with sigma_s the
    // albedo times extinction, and the albedo (and g) taken at draw time, so editing them needs no new samples.
    std::vector<float> weights;
    std::vector<glm::vec3> extinction;   // sigma_t(b_i) per channel
    std::vector<glm::vec2> region;       // [lo, hi] of the density slab holding b_i along parameters.regionAxis
    std::vector<glm::vec3> image;        // b_i mirrored across the nearest boundary of its region
    std::vector<BoundaryBall> boundary;  // the SH hold exp(-tau) minus share times its transmittance
    std::vector<float> sh;               // [sample][channel][coefficient]; read them through coefficients()
    std::vector<float> truncationError;  // fraction of the squared norm of exp(-tau) the ball and SH miss
    // The object's closed mesh in its own space as the preprocessor loaded it
    // (checked, zero-area faces dropped, faces outward), or empty. A render whose
    // object still has the fingerprint takes it from here instead of parsing the
    // mesh file again (core/loaded_scene.h), which took longer than the samples.
    TriangleMesh mesh;

    // A set read from a file leaves sh empty and reads the coefficients from the
    // file the first time they are asked for, from any thread: ss with traced
    // light never asks (they are most of a sample file's bytes, and copying
    // them was a tenth of the command's processor time). They were checked when the file
    // was read; a file that no longer holds the same bytes, or is gone, throws
    // Error("FILE: ..."). Filling sh replaces them.
    std::shared_ptr<const CoefficientsInFile> coefficientsInFile;

    size_t size() const { return positions.size(); }
    size_t coefficientsPerSample() const { return size_t(channels) * shOrder * shOrder; }
    // The SH coefficients, [sample][channel][coefficient].
    const std::vector<float>& coefficients() const;
};

inline constexpr uint32_t kSampleFileVersion = 8;
// SH bands a sample file may hold: the most the runtime evaluates (runtime/internal/sample_light.glsl).
inline constexpr uint32_t kMaxSampleShOrder = 8;

// Writes atomically (temporary file + rename).
void writeSampleFile(const std::filesystem::path& file, const SampleSet& samples);
// Throws Error("FILE: problem") on a wrong magic or version, truncation, a size that
// does not match the counts, a bad checksum or a non-finite value.
SampleSet readSampleFile(const std::filesystem::path& file);
// The same checks on bytes already in memory; name is used in messages.
SampleSet parseSampleFile(std::span<const char> bytes, const std::string& name);

}  // namespace lucent
