#pragma once
// Lucent's runtime as a library (thesis 3.4). A host that draws its own frame
// with OpenGL 4.5 creates a ScatteringRenderer on its current context, gives it
// the translucent objects (mesh + sample set) and the lights, and calls draw()
// with its framebuffer bound: the renderer adds the objects' reflected surfaces
// and the light they scatter, occluded by the host's depth. Inside, a frame is
// the frame targets followed by a list of passes (runtime/internal/render_pass.h).
#include <memory>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "core/method.h"
#include "core/sample_set.h"
#include "core/scattering_grid.h"
#include "core/scene.h"
#include "core/triangle_mesh.h"
#include "core/volume_object.h"
#include "runtime/opengl.h"
#include "runtime/view_setup.h"

namespace lucent {

struct TranslucentObject {
    const TriangleMesh* mesh;            // boundary, drawn for the surface and the depth passes
    const SampleSet* samples;            // from lucent preprocess, in the mesh's space; must outlive the renderer
    double g = 0.0;                      // Henyey-Greenstein mean cosine of the medium
    std::optional<SurfaceDesc> surface;  // reflected surface term, if any
    std::vector<const TriangleMesh*> blockers;  // opaque meshes inside: the camera's rays stop there
    Rgb albedo{0.0};                     // sigma_s / sigma_t, for optically thick objects (SampleScheme::OpticallyThick)
    Similarity placement;                // where the mesh, blockers and samples stand in the world
    // The object's medium for tracing the light to each sample (DrawOptions::tracedLight),
    // or null: the samples' SH alone. Must outlive the renderer.
    const VolumeObject* volume = nullptr;
};

// A scene object with its sample set, as the renderer takes it (both must outlive
// the renderer): its mesh and blockers in its own space, placed by its transform.
TranslucentObject translucentObjectFor(const VolumeObject& object, const SampleSet& samples);

// The scattering pass's proxy fragments in one frame: shaded (fragment shader
// invocations, after the early depth test) and kept (not discarded; with
// DrawOptions::discardBelow, those whose Gaussian is above the cut-off).
struct ScatterFragments {
    unsigned long long shaded = 0, kept = 0;
};

struct DrawOptions {
    bool surface = true;
    bool scattering = true;
    GlName hostDepthTexture = 0;  // the host's depth (0: nothing occludes)
    // Scales every medium's sigma_t and sigma_s at constant albedo. Exact up to the
    // SH truncation: the stored attenuation exp(-tau) becomes exp(-k tau) = psi^k.
    float extinctionScale = 1.0f;
    // Diagnostics: discard scattering fragments whose Gaussian line integral is
    // below this fraction of its largest possible value (0: keep all).
    float discardBelow = 0.0f;
    // Diagnostics: when set, the scattering pass counts its proxies' fragments
    // here (the render benchmark's useful fragments, with discardBelow).
    struct ScatterFragments* fragments = nullptr;
    // The single-scattering pass at 1/k of the resolution on each axis (k = 1, 2
    // or 4), upsampled along the objects' depth: its cost falls by about k^2.
    // 0: the measured default (scatterScaleFor, docs/runtime.md).
    int scatterScale = 0;
    // Each sample's light traced through the objects' volumes (TranslucentObject::volume)
    // on the CPU, one ray per sample and light, when the lights or placements change;
    // false: read from the SH expansion of its attenuation (thesis 3.3), which
    // smears narrow shadows and does not see the other objects (docs/accuracy.md,
    // traced light). Objects without a volume always read their SH, and so do
    // those whose samples times lights, 16 bytes each, exceed one shader storage block.
    bool tracedLight = true;
};

// The reduction DrawOptions::scatterScale 0 picks: the largest of 1, 2 and 4
// whose reduced pixel is at most kReducedPixelPerRadius of the samples' mean
// Poisson radius on screen (radiusPixels: the smallest over the objects, at
// their distance). Measured (docs/runtime.md): the bunny at 800x800 (8.3 px)
// keeps its error at 1/4; CGAL's elephant at 256x256 (1.4 px: legs, ears and
// trunk a few pixels across) went from 5.1% to 10.0% at 1/2 and 16% at 1/4.
inline constexpr double kReducedPixelPerRadius = 0.75;
int scatterScaleFor(double radiusPixels);

class ScatteringRenderer {
public:
    // On the current context, once loadGl has loaded Lucent's functions from it
    // (runtime/opengl.h; OffscreenContext does it); Error otherwise.
    // cutoff: a Gaussian is drawn where it exceeds this fraction of its peak.
    explicit ScatteringRenderer(double cutoff = kDefaultGaussianCutoff);
    ~ScatteringRenderer();
    ScatteringRenderer(const ScatteringRenderer&) = delete;
    ScatteringRenderer& operator=(const ScatteringRenderer&) = delete;

    // Objects are numbered in the order they are added, from 0.
    void addObject(const TranslucentObject& object);
    // Removes object index; those after it move down by one.
    void removeObject(size_t index);
    // Gives object index new samples (its medium changed and it was preprocessed
    // again, say) and the volume of that medium to trace its light through
    // (TranslucentObject::volume; null: its SH); its mesh and placement stay.
    void setSamples(size_t index, const SampleSet& samples, const VolumeObject* volume);
    size_t objectCount() const;
    // Moves, turns or scales object index (any similarity, every frame if need be:
    // nothing is uploaded; isotropic media recompute their samples' light once).
    // A multiple-scattering grid was solved for where the objects stood: it does
    // not follow (clear it, solve again).
    void setPlacement(size_t index, const Similarity& placement);
    void setLights(const std::vector<Light>& lights);
    // Light scattered twice or more, as a volumetric method solved it for the
    // current lights (hybrid/: --method lbl); drawn after single scattering.
    // Copied to the GPU at once. DrawOptions::extinctionScale does not apply to it.
    void addScatteringGrid(const ScatteringGrid& grid);
    void clearScatteringGrids();
    size_t sampleCount() const;

    // Draws into the framebuffer bound to GL_DRAW_FRAMEBUFFER (a float colour
    // attachment keeps the radiance linear), within view.width x view.height.
    void draw(const ViewSetup& view, const DrawOptions& options = {});

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace lucent
