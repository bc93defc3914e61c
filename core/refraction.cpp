#include "core/refraction.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace lucent {
namespace {

// Rays leave a boundary point this far along, in units of the object's diagonal:
// past the single-precision traversal's uncertainty, far below any feature.
constexpr double kOffset = 1e-7;

// A unit vector pair spanning the plane normal to unit n.
std::array<Vec3, 2> tangentFrame(const Vec3& n) {
    const Vec3 t1 = glm::normalize(std::abs(n.x) < 0.9 ? glm::cross(n, Vec3(1, 0, 0)) : glm::cross(n, Vec3(0, 1, 0)));
    return {t1, glm::cross(n, t1)};
}

// The boundary hit at distance t along origin + t dir on face f.
BoundaryHit hitAt(const VolumeObject& o, uint32_t f, double t, const Vec3& origin, const Vec3& dir) {
    const Vec3 p = origin + t * dir;
    const auto& tri = o.mesh().triangles[f];
    const Vec3& a = o.mesh().positions[tri[0]];
    const Vec3 face = glm::cross(o.mesh().positions[tri[1]] - a, o.mesh().positions[tri[2]] - a);
    Vec3 n = o.shadingNormal(f, p);
    if (glm::dot(n, face) < 0.0) n = -n;
    // Entering or leaving by the face's own orientation, which the closed mesh makes consistent.
    return BoundaryHit{t, p, n, glm::dot(dir, face) < 0.0, f};
}

// Where the ray meets face f, if it meets it inside the triangle and past the
// offset (Moller and Trumbore's test, in double precision). For rays a hair's
// breadth beside one whose first crossing is f (the Newton solve's difference
// quotients and the bundle's side rays below): that crossing stays f unless
// the ray slips over the triangle's edge, and then the whole mesh is asked.
std::optional<BoundaryHit> hitOnFace(const VolumeObject& o, uint32_t f, const Vec3& origin, const Vec3& dir) {
    const auto& tri = o.mesh().triangles[f];
    const Vec3& a = o.mesh().positions[tri[0]];
    const Vec3 e1 = o.mesh().positions[tri[1]] - a, e2 = o.mesh().positions[tri[2]] - a;
    const Vec3 across = glm::cross(dir, e2);
    const double det = glm::dot(e1, across);
    if (!(std::abs(det) > 0.0)) return std::nullopt;
    const Vec3 fromA = origin - a;
    const double u = glm::dot(fromA, across) / det;
    if (!(u >= 0.0 && u <= 1.0)) return std::nullopt;
    const Vec3 q = glm::cross(fromA, e1);
    const double v = glm::dot(dir, q) / det;
    if (!(v >= 0.0 && u + v <= 1.0)) return std::nullopt;
    const double t = glm::dot(e2, q) / det;
    if (!(t > kOffset * o.boundary().bounds().diagonal())) return std::nullopt;
    return hitAt(o, f, t, origin, dir);
}

// No face to try first: ask the whole mesh.
constexpr uint32_t kAnyFace = std::numeric_limits<uint32_t>::max();

// nextBoundaryHit, tried first on face f unless it is kAnyFace (hitOnFace).
std::optional<BoundaryHit> nextBoundaryHitNear(const VolumeObject& o, const Vec3& origin, const Vec3& dir, uint32_t f) {
    if (f != kAnyFace)
        if (std::optional<BoundaryHit> hit = hitOnFace(o, f, origin, dir)) return hit;
    return nextBoundaryHit(o, origin, dir);
}

// The outgoing direction of a ray leaving x inside o along w, refracted out at
// the boundary, and where it left; none under total internal reflection.
struct Exit {
    Vec3 point, direction;
    double inside, cosine;  // distance from x; cosine to the normal inside
    uint32_t face;
};
// nearFace: a ray a hair's breadth beside this one left through it (hitOnFace).
std::optional<Exit> refractOut(const VolumeObject& o, const Vec3& x, const Vec3& w, uint32_t nearFace = kAnyFace) {
    const std::optional<BoundaryHit> hit = nextBoundaryHitNear(o, x, w, nearFace);
    if (!hit || hit->entering) return std::nullopt;
    const double cosine = glm::dot(w, hit->normal);
    if (!(cosine > 0.0)) return std::nullopt;  // the shading normal turns away from the ray
    const std::optional<Vec3> out = refractedDirection(w, -hit->normal, o.desc().medium.ior);
    if (!out) return std::nullopt;
    return Exit{hit->point, *out, hit->t, cosine, hit->face};
}

// The ray refracted into o where a ray from outside along w first meets it.
struct Entry {
    Vec3 point, direction;
    double cosine;  // of the incident ray to the normal
    uint32_t face;
};
std::optional<Entry> refractIn(const VolumeObject& o, const Vec3& origin, const Vec3& w, uint32_t nearFace = kAnyFace) {
    const std::optional<BoundaryHit> hit = nextBoundaryHitNear(o, origin, w, nearFace);
    if (!hit || !hit->entering) return std::nullopt;
    const double cosine = -glm::dot(w, hit->normal);
    if (!(cosine > 0.0)) return std::nullopt;
    const std::optional<Vec3> in = refractedDirection(w, hit->normal, 1.0 / o.desc().medium.ior);
    if (!in) return std::nullopt;
    return Entry{hit->point, *in, cosine, hit->face};
}

}  // namespace

double fresnelReflectance(double cosIncident, double eta) {
    const double cosI = std::clamp(cosIncident, 0.0, 1.0);
    const double sin2T = eta * eta * (1.0 - cosI * cosI);
    if (sin2T >= 1.0) return 1.0;
    const double cosT = std::sqrt(1.0 - sin2T);
    // Amplitude ratios for light polarised perpendicular and parallel to the plane of incidence.
    const double rs = (eta * cosI - cosT) / (eta * cosI + cosT);
    const double rp = (cosI - eta * cosT) / (cosI + eta * cosT);
    return 0.5 * (rs * rs + rp * rp);
}

double diffuseFresnelReflectance(double eta) {
    // Below mu_c (past the critical angle) R = 1 and gives mu_c^2. Above it R
    // goes as sqrt(mu - mu_c) near mu_c: with mu = mu_c + (1 - mu_c) u^2 the
    // integrand is smooth in u, and Simpson's rule on 512 intervals is exact to ~1e-10.
    const double muC = eta > 1.0 ? std::sqrt(1.0 - 1.0 / (eta * eta)) : 0.0;
    constexpr int kIntervals = 512;
    double sum = 0.0;
    for (int i = 0; i <= kIntervals; ++i) {
        const double u = double(i) / kIntervals, mu = muC + (1.0 - muC) * u * u;
        const double w = i == 0 || i == kIntervals ? 1.0 : (i % 2 ? 4.0 : 2.0);
        sum += w * fresnelReflectance(mu, eta) * mu * 2.0 * (1.0 - muC) * u;
    }
    return muC * muC + 2.0 * sum / (3.0 * kIntervals);
}

std::optional<Vec3> refractedDirection(const Vec3& w, const Vec3& facing, double eta) {
    const double cosI = -glm::dot(w, facing);
    const double sin2T = eta * eta * std::max(0.0, 1.0 - cosI * cosI);
    if (sin2T >= 1.0) return std::nullopt;
    const double cosT = std::sqrt(1.0 - sin2T);
    return glm::normalize(eta * w + (eta * cosI - cosT) * facing);
}

std::optional<BoundaryHit> nextBoundaryHit(const VolumeObject& o, const Vec3& origin, const Vec3& dir) {
    const double offset = kOffset * o.boundary().bounds().diagonal();
    if (const std::optional<Crossing> c = o.boundary().firstCrossing(origin, dir, offset))
        return hitAt(o, c->face, c->t, origin, dir);
    return std::nullopt;
}

Vec3 towardLight(const Light& light, const Vec3& y) {
    return light.type == Light::Type::Point ? glm::normalize(light.position - y) : -light.direction;
}

namespace {

// The Newton solve of lightThroughBoundary for x: the unknown is the direction
// at x, as two coordinates p about the straight line to the light, and the
// residual how far the ray along it, refracted out, misses the light.
struct ExitSolve {
    const VolumeObject& o;
    const Light& light;
    Vec3 x, straight;
    std::array<Vec3, 2> frame;

    ExitSolve(const VolumeObject& object, const Light& l, const Vec3& at)
        : o(object), light(l), x(at), straight(towardLight(l, at)), frame(tangentFrame(straight)) {}
    Vec3 direction(const Vec2& p) const { return glm::normalize(straight + p.x * frame[0] + p.y * frame[1]); }
    // nearFace: try that face first (hitOnFace).
    std::optional<Vec2> residual(const Vec2& p, Exit* exit, uint32_t nearFace) const {
        const std::optional<Exit> e = refractOut(o, x, direction(p), nearFace);
        if (!e) return std::nullopt;
        if (exit) *exit = *e;
        const Vec3 miss = e->direction - towardLight(light, e->point);
        return Vec2(glm::dot(miss, frame[0]), glm::dot(miss, frame[1]));
    }
    // Damped Newton from p. local: the difference quotients and the steps try
    // the face the current ray leaves by first, as the iterates move a little
    // at a time (the caller checks the solution against the whole mesh); this
    // halves the traversals of the mesh a solve makes. Otherwise only the
    // difference quotients do, a hair's breadth from the current ray.
    std::optional<Exit> newton(Vec2 p, bool local) const {
        Exit exit{};
        std::optional<Vec2> r = residual(p, &exit, kAnyFace);
        for (int iteration = 0; r && iteration < 20; ++iteration) {
            if (glm::length(*r) < 1e-9) return exit;
            constexpr double h = 1e-7;
            const std::optional<Vec2> rx = residual(p + Vec2(h, 0.0), nullptr, exit.face);
            const std::optional<Vec2> ry = residual(p + Vec2(0.0, h), nullptr, exit.face);
            if (!rx || !ry) return std::nullopt;
            const Vec2 cx = (*rx - *r) / h, cy = (*ry - *r) / h;
            const double det = cx.x * cy.y - cy.x * cx.y;
            if (!(std::abs(det) > 1e-300)) return std::nullopt;
            Vec2 step(-(cy.y * r->x - cy.x * r->y) / det, -(-cx.y * r->x + cx.x * r->y) / det);
            // Halve the step until the residual shrinks (or the ray refracts at all).
            const uint32_t near = local ? exit.face : kAnyFace;
            std::optional<Vec2> next;
            Exit nextExit{};
            for (int halvings = 0; halvings < 10; ++halvings, step *= 0.5) {
                next = residual(p + step, &nextExit, near);
                if (next && glm::length(*next) < glm::length(*r)) break;
                next.reset();
            }
            if (!next) return std::nullopt;
            p += step;
            r = next;
            exit = nextExit;
        }
        return std::nullopt;
    }
};

// The ray leaving o towards the light from x: Newton from the straight line,
// then from lines turned towards the boundary's normal (the refracted ray
// inside is nearer the normal). Solved locally first; where something of the
// mesh lies between x and the solution's exit, solved again with every step
// asking the whole mesh.
std::optional<Exit> exitTowardLight(const VolumeObject& o, const Light& light, const Vec3& x) {
    const ExitSolve solve(o, light, x);
    const std::optional<BoundaryHit> straightHit = nextBoundaryHit(o, x, solve.straight);
    if (!straightHit) return std::nullopt;
    const Vec3 towardsNormal = straightHit->normal - glm::dot(straightHit->normal, solve.straight) * solve.straight;
    auto fromTilts = [&](bool local) -> std::optional<Exit> {
        for (double tilt : {0.0, 0.5, 1.0}) {
            const Vec2 p(glm::dot(tilt * towardsNormal, solve.frame[0]),
                         glm::dot(tilt * towardsNormal, solve.frame[1]));
            if (std::optional<Exit> e = solve.newton(p, local)) return e;
        }
        return std::nullopt;
    };
    const std::optional<Exit> local = fromTilts(true);
    if (!local) return std::nullopt;
    const std::optional<BoundaryHit> first = nextBoundaryHit(o, x, glm::normalize(local->point - x));
    if (first && first->face == local->face) return local;
    return fromTilts(false);
}

}  // namespace

std::optional<RefractedArrival> lightThroughBoundary(const VolumeObject& o, const Light& light, const Vec3& x) {
    const bool point = light.type == Light::Type::Point;
    const double diagonal = o.boundary().bounds().diagonal();
    const std::optional<Exit> solved = exitTowardLight(o, light, x);
    if (!solved) return std::nullopt;
    const Vec3 y = solved->point, toLight = towardLight(light, y);
    const double distance = point ? glm::length(light.position - y) : kInfinity;
    // The light's way out there must not cross the object again.
    if (o.boundary().firstHit(y + kOffset * diagonal * toLight, toLight) < distance) return std::nullopt;
    // The bundle: two rays beside the solution's, from the light (point: turned
    // by h radians; directional: moved by h diagonals), refracted in, measured on
    // the plane at x across the central ray. Its area there per unit solid angle
    // (or area) at the light is the irradiance's focusing.
    constexpr double h = 1e-5;
    const double step = point ? h : h * diagonal;
    const Vec3 emitted = -toLight;
    const Vec3 source = point ? light.position : y + 2.0 * diagonal * toLight;
    const std::array<Vec3, 2> across = tangentFrame(emitted);
    auto ray = [&](int k, uint32_t nearFace) -> std::optional<Entry> {
        const Vec3 offset = k == 0 ? Vec3(0.0) : step * across[size_t(k - 1)];
        return point ? refractIn(o, source, glm::normalize(emitted + offset), nearFace)
                     : refractIn(o, source + offset, emitted, nearFace);
    };
    const std::optional<Entry> centre = ray(0, kAnyFace);
    if (!centre) return std::nullopt;
    const std::optional<Entry> side1 = ray(1, centre->face), side2 = ray(2, centre->face);
    if (!side1 || !side2) return std::nullopt;
    auto onPlane = [&](const Entry& e) {
        return e.point +
               glm::dot(x - e.point, centre->direction) / glm::dot(e.direction, centre->direction) * e.direction;
    };
    const Vec3 p0 = onPlane(*centre);
    // The central ray must come back to x: the solve and the bundle agree.
    if (glm::length(p0 - x) > 1e-6 * diagonal) return std::nullopt;
    const double area = glm::length(glm::cross(onPlane(*side1) - p0, onPlane(*side2) - p0));
    if (!(area > 0.0)) return std::nullopt;
    const double transmitted = 1.0 - fresnelReflectance(centre->cosine, 1.0 / o.desc().medium.ior);
    // power: the point light's intensity, or the directional light's irradiance (core/scene.h);
    // a spot's cone along the way the light leaves it.
    const Rgb irradiance = light.power * (transmitted * spotFalloff(light, emitted) * step * step / area);
    return RefractedArrival{glm::normalize(y - x), solved->inside, irradiance, y, toLight, distance};
}

}  // namespace lucent
