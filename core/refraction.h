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
#include <algorithm>
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
    uint32_t face;  // the mesh triangle it meets
};

// The first boundary crossing of object o at t > a small offset along origin + t dir.
std::optional<BoundaryHit> nextBoundaryHit(const VolumeObject& o, const Vec3& origin, const Vec3& dir);

// A ray followed through refracting boundaries with both ways kept at each one
// (the single-scattering reference's camera rays, and the environment's
// background): reflected with Fresnel's share R and refracted with (1 - R) and
// the crossing's 1/n^2 of radiance (n^2 going out), each way a branch of its
// own, until a branch carries less than kLeastBranchWeight of the ray's
// radiance or has crossed kMaxBranchEvents boundaries. Each stretch between
// boundaries (or blockers) is handed to visit, which returns what the stretch
// passes on (its transmittance): the branches after it carry that much less.
// Objects must not overlap: each boundary separates one medium from the air.
struct RayStretch {
    Vec3 origin, direction;      // direction unit
    const VolumeObject* inside;  // the object the stretch runs through, or null (the air)
    double length;               // to the next boundary or blocker; infinity when it leaves every object
    bool blocked;                // it ends on an opaque blocker
    Rgb weight;                  // the share of the ray's radiance it carries, at its origin
};
inline constexpr double kLeastBranchWeight = 1e-5;
inline constexpr int kMaxBranchEvents = 256;
template <class Visit>
void followRayBranches(const std::vector<VolumeObject>& objects, const Vec3& origin, const Vec3& dir,
                       const VolumeObject* inside, const Visit& visit);

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
// The unit direction from y towards the light (its centre, for a point light).
Vec3 towardLight(const Light& light, const Vec3& y);

namespace detail {

// One stretch of followRayBranches from x along w, then both ways at the boundary it meets.
template <class Visit>
void followBranch(const std::vector<VolumeObject>& objects, const Vec3& x, const Vec3& w, const VolumeObject* inside,
                  const Rgb& weight, int events, const Visit& visit) {
    if (events >= kMaxBranchEvents || std::max({weight.r, weight.g, weight.b}) < kLeastBranchWeight) return;
    // What the ray meets next: a boundary of the object it is in, or of any object from the air.
    std::optional<BoundaryHit> hit;
    const VolumeObject* hitObject = inside;
    if (inside) {
        hit = nextBoundaryHit(*inside, x, w);
    } else {
        for (const VolumeObject& o : objects)
            if (const std::optional<BoundaryHit> h = nextBoundaryHit(o, x, w); h && (!hit || h->t < hit->t))
                hit = h, hitObject = &o;
    }
    double tBlocker = kInfinity;
    for (const VolumeObject& o : objects) tBlocker = std::min(tBlocker, o.firstBlockerHit(x, w));
    const bool blocked = tBlocker < (hit ? hit->t : kInfinity);
    const Rgb carried = weight * visit(RayStretch{x, w, inside,
                                                  blocked ? tBlocker
                                                  : hit   ? hit->t
                                                          : kInfinity,
                                                  blocked, weight});
    if (!hit || blocked) return;
    // Fresnel's split at the boundary (as the path tracer's, with both ways kept).
    const double n = hitObject->desc().medium.ior;
    const Vec3 facing = hit->entering ? hit->normal : -hit->normal;
    const double eta = hit->entering ? 1.0 / n : n;
    const double cosine = -glm::dot(w, facing);
    // A shading normal turned away from the ray: it goes through unbent.
    const std::optional<Vec3> refracted = cosine > 0.0 ? refractedDirection(w, facing, eta) : std::optional<Vec3>(w);
    const double reflectance = !refracted ? 1.0 : cosine > 0.0 ? fresnelReflectance(cosine, eta) : 0.0;
    if (reflectance > 0.0)
        followBranch(objects, hit->point, reflectedDirection(w, hit->normal), inside, carried * reflectance, events + 1,
                     visit);
    if (refracted) {
        // Radiance over n^2 is conserved across the boundary (Veach 1997, 5.2).
        const double crossing = cosine > 0.0 ? (hit->entering ? 1.0 / (n * n) : n * n) : 1.0;
        followBranch(objects, hit->point, *refracted, hit->entering ? hitObject : nullptr,
                     carried * ((1.0 - reflectance) * crossing), events + 1, visit);
    }
}

}  // namespace detail

template <class Visit>
void followRayBranches(const std::vector<VolumeObject>& objects, const Vec3& origin, const Vec3& dir,
                       const VolumeObject* inside, const Visit& visit) {
    detail::followBranch(objects, origin, dir, inside, Rgb(1.0), 0, visit);
}

}  // namespace lucent
