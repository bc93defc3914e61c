#include "core/refraction.h"

#include <algorithm>
#include <array>
#include <cmath>

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

// The outgoing direction of a ray leaving x inside o along w, refracted out at
// the boundary, and where it left; none under total internal reflection.
struct Exit {
    Vec3 point, direction;
    double inside, cosine;  // distance from x; cosine to the normal inside
};
std::optional<Exit> refractOut(const VolumeObject& o, const Vec3& x, const Vec3& w) {
    const std::optional<BoundaryHit> hit = nextBoundaryHit(o, x, w);
    if (!hit || hit->entering) return std::nullopt;
    const double cosine = glm::dot(w, hit->normal);
    if (!(cosine > 0.0)) return std::nullopt;  // the shading normal turns away from the ray
    const std::optional<Vec3> out = refractedDirection(w, -hit->normal, o.desc().medium.ior);
    if (!out) return std::nullopt;
    return Exit{hit->point, *out, hit->t, cosine};
}

// The ray refracted into o where a ray from outside along w first meets it.
struct Entry {
    Vec3 point, direction;
    double cosine;  // of the incident ray to the normal
};
std::optional<Entry> refractIn(const VolumeObject& o, const Vec3& origin, const Vec3& w) {
    const std::optional<BoundaryHit> hit = nextBoundaryHit(o, origin, w);
    if (!hit || !hit->entering) return std::nullopt;
    const double cosine = -glm::dot(w, hit->normal);
    if (!(cosine > 0.0)) return std::nullopt;
    const std::optional<Vec3> in = refractedDirection(w, hit->normal, 1.0 / o.desc().medium.ior);
    if (!in) return std::nullopt;
    return Entry{hit->point, *in, cosine};
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
    if (const std::optional<Crossing> c = o.boundary().firstCrossing(origin, dir, offset)) {
        const Vec3 p = origin + c->t * dir;
        const auto& tri = o.mesh().triangles[c->face];
        const Vec3& a = o.mesh().positions[tri[0]];
        const Vec3 face = glm::cross(o.mesh().positions[tri[1]] - a, o.mesh().positions[tri[2]] - a);
        Vec3 n = o.shadingNormal(c->face, p);
        if (glm::dot(n, face) < 0.0) n = -n;
        // Entering or leaving by the face's own orientation, which the closed mesh makes consistent.
        return BoundaryHit{c->t, p, n, glm::dot(dir, face) < 0.0};
    }
    return std::nullopt;
}

std::optional<RefractedArrival> lightThroughBoundary(const VolumeObject& o, const Light& light, const Vec3& x) {
    const bool point = light.type == Light::Type::Point;
    const double diagonal = o.boundary().bounds().diagonal();
    auto target = [&](const Vec3& y) { return point ? glm::normalize(light.position - y) : -light.direction; };
    // The unknown: the direction at x, as two coordinates about the straight line to the light.
    const Vec3 straight = point ? glm::normalize(light.position - x) : -light.direction;
    const std::array<Vec3, 2> frame = tangentFrame(straight);
    auto direction = [&](const Vec2& p) { return glm::normalize(straight + p.x * frame[0] + p.y * frame[1]); };
    // How far the refracted ray's direction misses the light, in the same frame.
    auto residual = [&](const Vec2& p, Exit* exit) -> std::optional<Vec2> {
        const std::optional<Exit> e = refractOut(o, x, direction(p));
        if (!e) return std::nullopt;
        if (exit) *exit = *e;
        const Vec3 miss = e->direction - target(e->point);
        return Vec2(glm::dot(miss, frame[0]), glm::dot(miss, frame[1]));
    };
    // Damped Newton from the straight line, then from lines turned towards the
    // boundary's normal (the refracted ray inside is nearer the normal).
    std::optional<Exit> solved;
    const std::optional<BoundaryHit> straightHit = nextBoundaryHit(o, x, straight);
    if (!straightHit) return std::nullopt;
    const Vec3 towardsNormal = straightHit->normal - glm::dot(straightHit->normal, straight) * straight;
    for (double tilt : {0.0, 0.5, 1.0}) {
        Vec2 p(glm::dot(tilt * towardsNormal, frame[0]), glm::dot(tilt * towardsNormal, frame[1]));
        Exit exit{};
        std::optional<Vec2> r = residual(p, &exit);
        for (int iteration = 0; r && iteration < 20; ++iteration) {
            if (glm::length(*r) < 1e-9) {
                solved = exit;
                break;
            }
            constexpr double h = 1e-7;
            const std::optional<Vec2> rx = residual(p + Vec2(h, 0.0), nullptr);
            const std::optional<Vec2> ry = residual(p + Vec2(0.0, h), nullptr);
            if (!rx || !ry) break;
            const Vec2 cx = (*rx - *r) / h, cy = (*ry - *r) / h;
            const double det = cx.x * cy.y - cy.x * cx.y;
            if (!(std::abs(det) > 1e-300)) break;
            Vec2 step(-(cy.y * r->x - cy.x * r->y) / det, -(-cx.y * r->x + cx.x * r->y) / det);
            // Halve the step until the residual shrinks (or the ray refracts at all).
            std::optional<Vec2> next;
            Exit nextExit{};
            for (int halvings = 0; halvings < 10; ++halvings, step *= 0.5) {
                next = residual(p + step, &nextExit);
                if (next && glm::length(*next) < glm::length(*r)) break;
                next.reset();
            }
            if (!next) break;
            p += step;
            r = next;
            exit = nextExit;
        }
        if (solved) break;
    }
    if (!solved) return std::nullopt;
    const Vec3 y = solved->point, toLight = target(y);
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
    auto ray = [&](int k) -> std::optional<Entry> {
        const Vec3 offset = k == 0 ? Vec3(0.0) : step * across[size_t(k - 1)];
        return point ? refractIn(o, source, glm::normalize(emitted + offset)) : refractIn(o, source + offset, emitted);
    };
    const std::optional<Entry> centre = ray(0), side1 = ray(1), side2 = ray(2);
    if (!centre || !side1 || !side2) return std::nullopt;
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
