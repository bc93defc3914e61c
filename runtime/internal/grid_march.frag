#version 450 core
// The view pass of the hybrid (thesis 4.6.2): along the pixel's ray, within
// [t0, t1] (the nearest front face to the farthest back face, stopped by the
// host's depth and the blockers) and the grid's box,
//   L = int exp(-int sigma_t) source dt,
// marched in steps of half a voxel with the transmittance of each step exact
// for its midpoint's extinction. Outside the medium both grids hold 0, so air
// between two parts of a concave object adds and dims nothing.
//
// A grid with a refractive index (refracting) bends the ray from where it
// enters the grid's box until it leaves it, along the eikonal equation with the
// midpoint rule of the photon marching (hybrid/internal/photon_march.cl):
// dx/ds = v / n, dv/ds = grad n. Radiance over n^2 is what a ray carries
// unchanged through a varying index (Veach 1997, 5.2), so the light scattered
// at index n reaches the eye divided by n^2. The smoothed index reflects
// nothing, so where the ray first crosses the middle of the index's ramp it
// keeps Fresnel's transmission 1 - R(i) (hybrid/internal/photon_march.cl: the
// angle outside from the conserved component, sin i = |v x nu|). The host's
// depth clips only the straight part.
#include "gpu_layout.h"

uniform sampler2D raySegments;
uniform sampler3D source;      // rgb: sigma_s phi / (4 pi)
uniform sampler3D extinction;  // rgb: sigma_t
uniform mat4 inverseViewProjection;
uniform vec3 cameraPosition;
uniform vec2 viewportSize;
uniform vec3 boundsMin, boundsMax;
uniform float voxel;
uniform bool refracting;
uniform sampler3D refraction;  // x: n; yzw: grad n per world unit
uniform float ior;             // the medium's own index, inside

out vec4 colour;

// The step's share of the source, dimmed from its start: T (1 - e^{-s dt}) / s -> T dt as s -> 0.
vec3 stepWeight(vec3 sigmaT, vec3 stepT, float dt) {
    return mix(vec3(dt), (1.0 - stepT) / max(sigmaT, vec3(1e-30)), greaterThan(sigmaT * dt, vec3(1e-4)));
}

// Fresnel reflectance for light from air (unpolarised), cosine cosI, relative index n (core/refraction.cpp).
float fresnelFromAir(float cosI, float n) {
    float eta = 1.0 / n;
    float cosT = sqrt(max(0.0, 1.0 - eta * eta * (1.0 - cosI * cosI)));
    float rs = (eta * cosI - cosT) / (eta * cosI + cosT), rp = (cosI - eta * cosT) / (cosI + eta * cosT);
    return 0.5 * (rs * rs + rp * rp);
}

vec3 marchBent(vec3 x, vec3 dir) {
    vec3 scale = 1.0 / (boundsMax - boundsMin);
    float ds = 0.5 * voxel;
    vec3 v = texture(refraction, (x - boundsMin) * scale).x * dir;
    // A ray crosses the box in fewer; more is one caught circling (total internal reflection).
    int steps = clamp(int(ceil(4.0 * length(boundsMax - boundsMin) / ds)), 1, 16384);
    vec3 transmittance = vec3(1.0), radiance = vec3(0.0);
    bool entered = false;
    for (int i = 0; i < steps; ++i) {
        vec4 r = texture(refraction, (x - boundsMin) * scale);
        if (!entered && r.x >= 0.5 * (1.0 + ior) && dot(r.yzw, r.yzw) > 0.0) {
            entered = true;
            float sinI = length(cross(v, normalize(r.yzw)));
            transmittance *= 1.0 - fresnelFromAir(sqrt(max(0.0, 1.0 - sinI * sinI)), ior);
        }
        vec3 xm = x + 0.5 * ds * v / r.x, vm = v + 0.5 * ds * r.yzw;
        vec3 p = (xm - boundsMin) * scale;
        if (any(lessThan(p, vec3(0.0))) || any(greaterThan(p, vec3(1.0)))) break;
        vec4 rm = texture(refraction, p);
        vec3 sigmaT = texture(extinction, p).rgb;
        vec3 stepT = exp(-sigmaT * ds);
        radiance += transmittance * stepWeight(sigmaT, stepT, ds) * texture(source, p).rgb / (rm.x * rm.x);
        transmittance *= stepT;
        if (max(transmittance.r, max(transmittance.g, transmittance.b)) < 1e-6) break;
        x += ds * vm / rm.x;
        v += ds * rm.yzw;
    }
    return radiance;
}

void main() {
    vec2 segment = texelFetch(raySegments, ivec2(gl_FragCoord.xy), 0).rg;
    if (segment.x < 0.0 || segment.x >= segment.y) discard;
    vec2 ndc = gl_FragCoord.xy / viewportSize * 2.0 - 1.0;
    vec4 far = inverseViewProjection * vec4(ndc, 1.0, 1.0);
    vec3 dir = normalize(far.xyz / far.w - cameraPosition);
    // Clip [t0, t1] to the grid's box.
    vec3 inv = 1.0 / dir;
    vec3 a = (boundsMin - cameraPosition) * inv, b = (boundsMax - cameraPosition) * inv;
    float t0 = max(segment.x, max(max(min(a.x, b.x), min(a.y, b.y)), min(a.z, b.z)));
    float t1 = min(segment.y, min(min(max(a.x, b.x), max(a.y, b.y)), max(a.z, b.z)));
    if (t0 >= t1) discard;
    if (refracting) {
        float boxEntry = max(0.0, max(max(min(a.x, b.x), min(a.y, b.y)), min(a.z, b.z)));
        colour = vec4(marchBent(cameraPosition + boxEntry * dir, dir), 0.0);
        return;
    }
    int steps = clamp(int(ceil((t1 - t0) / (0.5 * voxel))), 1, 4096);
    float dt = (t1 - t0) / float(steps);
    vec3 scale = 1.0 / (boundsMax - boundsMin);
    vec3 transmittance = vec3(1.0), radiance = vec3(0.0);
    for (int i = 0; i < steps; ++i) {
        vec3 p = ((cameraPosition + (t0 + (float(i) + 0.5) * dt) * dir) - boundsMin) * scale;
        vec3 sigmaT = texture(extinction, p).rgb;
        vec3 stepT = exp(-sigmaT * dt);
        radiance += transmittance * stepWeight(sigmaT, stepT, dt) * texture(source, p).rgb;
        transmittance *= stepT;
        if (max(transmittance.r, max(transmittance.g, transmittance.b)) < 1e-6) break;
    }
    colour = vec4(radiance, 0.0);
}
