#pragma once
// The view through a refracting boundary (an object whose medium has ior != 1):
// for each pixel of the scattering's view, the camera ray refracted where it
// enters the object, through the shading normal the surface pass draws (Snell's
// law, core/refraction.h), with the share of radiance that comes out along it,
// (1 - R) / n^2 (Fresnel's transmission and the n^2 law of radiance, as the
// reference weights the same crossing), and its length inside up to where it
// leaves or meets a blocker. Where it leaves, Fresnel reflects a share R back
// inside (all of it past the critical angle): the ray goes on, reflected, for
// kRefractedStretches stretches in all. The scattering pass integrates each
// Gaussian along these stretches instead of the camera's ray (scatter.frag,
// REFRACTED_VIEW), one draw of the samples per stretch, each sample's proxy
// placed where that stretch of the pixels' rays passes through it (scatter.vert).
//
// Traced on the CPU, one ray per stretch and pixel and one to enter, when the
// view or the object's placement changes. A refracted ray that leaves the
// object and enters it again (a concave part behind) sees nothing beyond, and
// neither does the camera ray Fresnel reflects off the object.
#include <vector>

#include <glm/glm.hpp>

#include "core/similarity.h"
#include "core/volume_object.h"
#include "runtime/internal/gl.h"
#include "runtime/internal/gpu_layout.h"
#include "runtime/view_setup.h"

namespace lucent {

// Whether the scattering pass draws this object through its boundary, which
// refracts (ior != 1): its samples' light traced through the boundary
// (tracedRefractedLight) and its fragments attenuated from where the refracted
// ray enters (fromFront: attenuatesFromFront of its samples). Otherwise it
// draws the boundary as index-matched, and SsMethod::limitations says so.
inline bool drawnRefracted(double ior, bool fromFront, bool tracedLight) {
    return ior != 1.0 && fromFront && tracedLight;
}

// One stretch of a pixel's ray inside the object, in view space.
struct RefractedStretch {
    glm::vec4 origin;     // xyz: where it starts (the entry first); w: the share of the pixel's radiance
                          // it carries out ((1 - R) / n^2, times R at each reflection), 0: no such stretch
    glm::vec4 direction;  // xyz: unit; w: its length inside the object (view units)
};

// Per pixel, row by row from the bottom as OpenGL's window coordinates,
// kRefractedStretches stretches, the first one first. The object stands at
// placement (its own world: volume.placement()).
std::vector<RefractedStretch> refractedViewRays(const VolumeObject& volume, const Similarity& placement,
                                                const ViewSetup& view);

// The stretches as one RGBA32F array texture, layers 2k and 2k + 1 holding
// stretch k's origin and direction, for the view and placement they were traced for.
class RefractedView {
public:
    RefractedView() = default;
    ~RefractedView();
    RefractedView(RefractedView&& other) noexcept;
    RefractedView& operator=(RefractedView&& other) noexcept;
    RefractedView(const RefractedView&) = delete;
    RefractedView& operator=(const RefractedView&) = delete;
    // Whether the texture holds the rays of this volume, placement and view.
    bool current(const VolumeObject& volume, const Similarity& placement, const ViewSetup& view) const;
    void upload(const std::vector<RefractedStretch>& rays, const VolumeObject& volume, const Similarity& placement,
                const ViewSetup& view);
    void bind(GLuint unit) const;
    // How many stretches some pixel has (the draws the samples need), 0 to kRefractedStretches.
    int stretches() const { return stretches_; }

private:
    GLuint texture_ = 0;
    int stretches_ = 0;
    ViewSetup traced_;
    Similarity placement_;
    const VolumeObject* volume_ = nullptr;
};

}  // namespace lucent
