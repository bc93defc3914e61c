#pragma once
// The optical depth from each sample to each light, traced through the objects'
// meshes, densities and blockers (core/volume_object.h) rather than read from the
// SH expansion of psi_i. A shadow one part of an object casts on another (the
// loops of a knot) is a narrow feature of psi_i that 64 coefficients smear over
// its neighbourhood, and psi_i knows nothing of the other objects; the traced
// depth is exact for point and directional lights (docs/accuracy.md, traced
// light), at one ray per sample, light and object, traced in packets of
// neighbouring samples.
#include <vector>

#include <glm/glm.hpp>

#include "core/sample_set.h"
#include "core/scene.h"
#include "core/similarity.h"
#include "core/volume_object.h"

namespace lucent {

// An object as the renderer stands it: placement maps its own space into the
// renderer's world; the volume answers in its own world (its transform), which
// may differ.
struct TracedVolume {
    const VolumeObject* volume;
    Similarity placement;
};

// For the samples of one object standing at placement, at [i * lights.size() + j]:
// rgb the optical depth (sigma_t times the density path, every object summed)
// from sample i's centre to light j in the renderer's world units, and w = 1
// where a blocker stops the light. For a sphere light, the depth whose
// exponential is the mean transmittance over its cone (16 rays: soft shadows).
std::vector<glm::vec4> tracedOpticalDepths(const std::vector<TracedVolume>& volumes, const SampleSet& samples,
                                           const Similarity& placement, const std::vector<Light>& lights);

// The same for the samples of an object whose boundary refracts (ior != 1,
// volumes[own]): the light reaches each sample through the boundary
// (lightThroughBoundary, core/refraction.h), bent, not along the straight line.
// Two records per sample and light, at [2 (i * lights.size() + j)] and the one
// after: the optical depth as above, along the refracted way inside and the
// straight way on from the boundary through the other objects; and xyz the unit
// direction at the sample towards where the light enters, w the irradiance
// there per unit of the light's power (its Fresnel transmission and the
// focusing of its bundle; 0 where no ray of that light reaches the sample by
// one refraction).
std::vector<glm::vec4> tracedRefractedLight(const std::vector<TracedVolume>& volumes, size_t own,
                                            const SampleSet& samples, const std::vector<Light>& lights);

}  // namespace lucent
