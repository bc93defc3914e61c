#pragma once
// A sphere light (Light::radius > 0): a point light's intensity I spread over a
// sphere of radius R that emits uniformly (Lambertian) from its surface with
// the same total power 4 pi I, so that its radiance is I / (pi R^2). From a
// point x at distance d from its centre it covers the cone of half-angle
// asin(R / d), and light from every direction of that cone arrives with that
// radiance: the in-scattered light is the integral over the cone of
// p(w) L_e T(x, w), which tends to the point light's p I T / d^2 as R -> 0.
#include <optional>
#include <string>
#include <vector>

#include "core/math.h"
#include "core/scene.h"

namespace lucent {

struct SphereLightCone {
    Vec3 axis;          // unit, from x towards the centre
    double cosMax;      // cosine of the cone's half-angle
    double distance;    // d, from x to the centre
    double irradiance;  // L_e times the cone's solid angle per unit intensity: 2 (1 - cosMax) / R^2
};

// None where x lies inside the sphere or on it (it emits outwards only).
std::optional<SphereLightCone> sphereLightCone(const Vec3& centre, double radius, const Vec3& x);

// The direction through (u, v) in [0, 1)^2, uniform in solid angle over the cone.
Vec3 coneDirection(const SphereLightCone& cone, double u, double v);

// One line per sphere light and refracting object: every method takes the light
// through a refracting boundary as a point at its centre (core/refraction.h
// solves for one point), so its soft shadows and its extent are left out there.
std::vector<std::string> sphereLightsThroughBoundaries(const SceneDesc& scene);

// Distance from x along the unit direction w to the sphere's near side; the
// distance to the point of closest approach when w misses it (rounding at the rim).
double distanceToSphere(const Vec3& x, const Vec3& w, const Vec3& centre, double radius);

}  // namespace lucent
