#pragma once
// The environment the camera sees where the scene asks for it ("background":
// true): behind the objects, and through each index-matched one dimmed by
// e^{-tau}, tau the optical depth of the pixel's ray through every object on the
// way (the unscattered light; what the media scatter is the methods' own). An
// opaque blocker on the ray hides it. This is the reference's background
// (reference/reference_renderer.cpp), one ray through each pixel's centre, so that
// ss, lbl and mdom draw the same and add only their scattering.
#include <vector>

#include "core/image.h"
#include "core/loaded_scene.h"
#include "core/similarity.h"

namespace lucent {

// The background image at the scene camera's size, or an empty image when the
// scene has no environment or no background. Through an object with a
// refracting boundary (ior not 1) the ray is followed as the reference follows
// it (core/refraction.h, followRayBranches): reflected off the boundary and
// refracted through it, each way with its share, so the map is seen bent
// through the object and mirrored in it.
Image environmentBackground(const LoadedScene& scene, int threads);

// Where a host has moved things since the scene was loaded, as the viewer does.
struct BackgroundEdits {
    std::vector<Similarity> placements;  // each object's, in place of its own (VolumeObject::placement)
    double extinctionScale = 1.0;        // every sigma_t times this
    glm::dmat3 turn{1.0};                // the map's directions turned by this
    double scale = 1.0;                  // the map's radiance times this
};

// The same for the camera, the map and the objects given, moved by edits. With
// an object moved from where it was loaded, the rays go straight, and through
// a refracting object none of the map is drawn.
Image environmentBackground(const std::vector<VolumeObject>& objects, const EnvironmentMap& map, const Camera& camera,
                            const BackgroundEdits& edits, int threads);

}  // namespace lucent
