#pragma once
// Smooth dielectric boundaries, for every method that refracts: an object whose medium has
// an index of refraction n != 1 reflects and refracts light at its boundary
// (Fresnel's equations for unpolarised light, Snell's law about the shading
// normal the runtime draws). Outside every object the index is 1.
//
// Light from a point or directional source cannot reach a point inside such an
// object along a straight line, and a random path never hits a point light, so
// next-event estimation goes through the boundary: a Newton solve finds the
// direction at x whose ray, refracted out at the boundary, heads for the light
// (manifold next-event estimation, Hanika et al. 2015, one refraction), and the
// irradiance arriving there is the light's ray bundle refracted into the
// medium: the power per solid angle at the light over the area the bundle
// covers at x, found by tracing two neighbouring rays from the light.
#include <optional>
#include <vector>

#include "core/math.h"
#include "core/scene.h"
#include "core/volume_object.h"

namespace lucent {

// Fresnel reflectance of unpolarised light meeting a smooth boundary at cosine
// cosIncident (> 0) to its normal, eta = n_from / n_to. 1 past the critical angle.
double fresnelReflectance(double cosIncident, double eta);

// Fresnel reflectance averaged over a hemisphere of diffuse light (radiance the
// same from every direction, so cosine-weighted): 2 int_0^1 R(mu, eta) mu dmu.
// With eta = n (light inside an object of index n meeting the air) it is the
// share of diffuse light that the boundary keeps inside, all of it past the
// critical angle (Egan and Hilgeman's F_dr, here integrated, not fitted).
double diffuseFresnelReflectance(double eta);

// Direction w (unit) refracted through a boundary whose unit normal faces
// against w, eta = n_from / n_to; none under total internal reflection.
std::optional<Vec3> refractedDirection(const Vec3& w, const Vec3& facing, double eta);

// w mirrored about the boundary with unit normal n (either orientation).
inline Vec3 reflectedDirection(const Vec3& w, const Vec3& n) { return w - 2.0 * glm::dot(w, n) * n; }

// Where a ray next meets an object's boundary.
struct BoundaryHit {
    double t;
    Vec3 point;
    Vec3 normal;    // the unit shading normal, turned to the outside
    bool entering;  // the ray goes from outside to inside (by the face's own normal)
};

// The first boundary crossing of object o at t > a small offset along origin + t dir.
std::optional<BoundaryHit> nextBoundaryHit(const VolumeObject& o, const Vec3& origin, const Vec3& dir);

// Light reaching x, a point inside o, through o's boundary.
struct RefractedArrival {
    Vec3 toLight;    // unit, at x, towards the boundary point the light enters at
    double inside;   // distance from x to that point
    Rgb irradiance;  // on a plane facing toLight at x: after the Fresnel transmission and the
                     // bundle's focusing; no attenuation on the way (inside o, or by other objects)
    Vec3 entry;      // the boundary point the light enters at
    Vec3 outward;    // unit, from entry towards the light
    double outside;  // distance from entry to a point light; infinity for a directional one
};

// None where no ray of the light reaches x by one refraction (total internal
// reflection, the light's way blocked by the object itself, no convergence):
// then that light does not reach x directly. Of several such rays (caustics
// behind strongly curved parts) the solve finds the one nearest the straight line.
std::optional<RefractedArrival> lightThroughBoundary(const VolumeObject& o, const Light& light, const Vec3& x);

}  // namespace lucent
