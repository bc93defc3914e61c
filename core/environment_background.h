#pragma once
// The environment the camera sees where the scene asks for it ("background":
// true): behind the objects, and through each index-matched one dimmed by
// e^{-tau}, tau the optical depth of the pixel's ray through every object on the
// way (the unscattered light; what the media scatter is the methods' own). An
// opaque blocker on the ray hides it. This is the reference's background
// (reference/reference_renderer.cpp), one ray through each pixel's centre, so that
// ss, lbl and mdom draw the same and add only their scattering.
#include "core/image.h"
#include "core/loaded_scene.h"

namespace lucent {

// The background image at the scene camera's size, or an empty image when the
// scene has no environment or no background. A pixel whose ray meets an
// object with a refracting boundary (ior not 1) gets none: the light behind
// bends through it, which only the path tracer follows (environmentBackgroundLimitation).
Image environmentBackground(const LoadedScene& scene, int threads);

// What environmentBackground leaves out in this scene, for a method's
// limitations(); empty when nothing.
std::vector<std::string> environmentBackgroundLimitations(const LoadedScene& scene);

}  // namespace lucent
