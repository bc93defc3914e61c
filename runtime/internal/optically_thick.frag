#version 450 core
// Single scattering of an optically thick object (SampleScheme::OpticallyThick,
// runtime/internal/thick_pass.h): light dies within a sliver under the surface,
// thinner than the samples could resolve, so each pixel integrates its own view
// ray instead. Along the ray from the nearest front face, at distance u,
//   L = sum_j int sigma_s p_j E_j exp(-sigma_t (d_j(u) + u)) du,
// where d_j(u) is how far light j has come through the medium: the distance
// along its ray from where it entered the mesh, read from a map of the mesh seen
// from the light (entry_distances.h). Under a flat face lit at cos_l
// and seen at cos_v, d_j = u cos_v / cos_l and the integral is the Lommel-
// Seeliger law albedo p E cos_l / (cos_l + cos_v) whatever sigma_t is. The maps
// keep what a plane leaves out: light entering one face and leaving through
// the face beside it along an edge, light through a part thinner than the
// light's reach, and a face lit from behind. Index-matched boundary, as
// everywhere in the closed form; blockers lie deeper than the light goes. The
// light's entry is the mesh's nearest face, so light that leaves the object and
// enters it again is followed once (a third part on the way counts as medium).
in vec3 worldPosition;
in vec3 worldNormal;

#include "gpu_layout.h"
#include "lights.glsl"
#include "light_distance_maps.glsl"
#include "phase.glsl"

uniform int lightCount;
uniform vec3 cameraPosition;
uniform vec3 albedo;
uniform vec3 extinction;                 // sigma_t per channel, world units
uniform float g;                         // Henyey-Greenstein mean cosine
uniform sampler2D frontDepth;            // nearest front face of the translucent meshes
uniform sampler2D insideSegments;        // per pixel, the first interval inside them (segment.frag)
// Per light (entry_distances.h): the plane of its nearest entry into the mesh,
// the distance of the exit after it and of the entry after that.
uniform sampler2DArray entryPlanes;
uniform sampler2DArray entryExits;
uniform sampler2DArray nextEntries;

out vec4 colour;

// Steps along the ray. On each the optical depth d_j + u is taken as linear and
// integrated exactly, so a flat face lit by a distant light is exact with any
// number; the steps resolve edges and thin parts.
const int kSteps = 32;
// The ray is followed until the view's transmittance falls to e^-9 (1.2e-4).
const float kViewDepth = 9.0;

// How far light reaching distance s along its ray has come through the medium,
// from one texel's entries and exit: inside from the nearest entry e1 to the
// exit x1 and beyond the next entry e2 (from the light itself to x1 when x1
// comes first: the light stands inside).
float mediumBefore(float s, float e1, float x1, float e2) {
    if (x1 < e1) return min(s, x1) + max(s - e1, 0.0);
    return clamp(s - e1, 0.0, max(x1 - e1, 0.0)) + max(s - e2, 0.0);
}

// Where light j's ray through x meets the entry plane p (outward normal, and
// its dot product with the plane's points), in distance along the light;
// false where the ray runs along the plane.
bool entryAlong(int j, vec3 x, float s, vec4 p, out float e) {
    vec4 l = lights[j].position;
    vec3 travel = l.w > 0.5 ? normalize(x - l.xyz) : l.xyz;
    float facing = dot(p.xyz, travel);
    e = 0.0;
    if (!(facing < -1e-3)) return false;
    e = l.w > 0.5 ? (p.w - dot(p.xyz, l.xyz)) / facing : s + (p.w - dot(p.xyz, x)) / facing;
    return true;
}

// The fragment's own face (outward normal, a point). Where light enters
// through it, the entry planes of the texels about x are often its
// neighbours' (a curved mesh's facets): they put the entry up to a texel's
// size off, many mean free paths in a dense medium. Where a texel spans more
// than a mean free path, the length through the own face replaces the maps'
// if the two differ by less than two texels; a larger difference is the maps'
// to tell (light through another part first, an inner corner).
vec3 faceNormal;
vec3 facePoint;

// Light j's distance through the medium to x, bilinear over the texels of its
// maps about x (the lengths, not the distances, are interpolated: neighbouring
// texels may see a different number of parts). Each texel's entry is where x's
// own ray meets that texel's plane, exact on a flat face between texel centres.
float throughMedium(int j, vec3 x) {
    ivec2 size = textureSize(entryPlanes, 0).xy;
    int layer;
    vec2 st;
    float texel;
    if (!distanceMapTexel(j, x, size, layer, st, texel)) return 0.0;
    float s = distanceAlongLight(j, x);

    ivec2 base = ivec2(floor(st));
    vec2 f = st - vec2(base);
    float sum = 0.0, weight = 0.0;
    for (int k = 0; k < 4; ++k) {
        ivec3 p = ivec3(clamp(base + ivec2(k & 1, k >> 1), ivec2(0), size - 1), layer);
        float x1 = texelFetch(entryExits, p, 0).r;
        float e1 = 3.0e38;
        vec4 plane = texelFetch(entryPlanes, p, 0);
        if (plane.xyz != vec3(0.0) && !entryAlong(j, x, s, plane, e1)) continue;
        if (min(e1, x1) > 1e37) continue;  // a texel the mesh misses says nothing of x
        float w = ((k & 1) != 0 ? f.x : 1.0 - f.x) * ((k >> 1) != 0 ? f.y : 1.0 - f.y);
        sum += w * mediumBefore(s, e1, x1, texelFetch(nextEntries, p, 0).r);
        weight += w;
    }
    float d = weight > 0.0 ? sum / weight : 0.0;
    float own;
    float sigma = min(extinction.r, min(extinction.g, extinction.b));
    if (sigma * texel > 1.0 && entryAlong(j, x, s, vec4(faceNormal, dot(faceNormal, facePoint)), own) &&
        abs(s - own - d) < 2.0 * texel)
        d = max(s - own, 0.0);
    return d;
}

// sigma_s p E of light j at x, toward the eye along -view, per channel before the albedo.
vec3 scatteredAt(int j, vec3 x, vec3 view) {
    vec3 toLight;
    float falloff = 1.0;
    if (lights[j].position.w > 0.5) {
        toLight = lights[j].position.xyz - x;
        float d2 = dot(toLight, toLight);
        if (d2 <= 0.0) return vec3(0.0);
        toLight *= inversesqrt(d2);
        falloff = spotFalloff(j, -toLight) * inverseSquare(j, d2);
    } else {
        toLight = -lights[j].position.xyz;
    }
    return henyeyGreenstein(g, dot(-toLight, -view)) * lights[j].power.rgb * falloff;
}

// int exp(-t) over a step on which t runs linearly from a to b, per unit length.
vec3 meanTransmittance(vec3 a, vec3 b) {
    vec3 delta = b - a;
    vec3 exact = (exp(-a) - exp(-b)) / delta;
    vec3 small = exp(-a) * (1.0 - 0.5 * delta);
    return mix(exact, small, lessThan(abs(delta), vec3(1e-3)));
}

// The light scattered toward the eye along the stretch [a, b] of the view ray
// (eye distances), dimmed by the medium crossed on the way before a (a length).
vec3 alongStretch(float a, float b, float before, vec3 view) {
    float reach = min(b - a, kViewDepth / max(min(extinction.r, min(extinction.g, extinction.b)), 1e-30) - before);
    if (!(reach > 0.0)) return vec3(0.0);
    float h = reach / float(kSteps);
    vec3 sum = vec3(0.0);
    for (int j = 0; j < lightCount; ++j) {
        vec3 x = cameraPosition + a * view;
        vec3 fBefore = scatteredAt(j, x, view);
        vec3 depthBefore = extinction * (throughMedium(j, x) + before);
        for (int k = 1; k <= kSteps; ++k) {
            float u = h * float(k);
            x = cameraPosition + (a + u) * view;
            vec3 fAfter = scatteredAt(j, x, view);
            vec3 depthAfter = extinction * (throughMedium(j, x) + before + u);
            sum += 0.5 * (fBefore + fAfter) * extinction * h * meanTransmittance(depthBefore, depthAfter);
            fBefore = fAfter;
            depthBefore = depthAfter;
        }
    }
    return sum;
}

void main() {
    // Only the nearest front face is visible; concave meshes draw several per pixel.
    if (gl_FragCoord.z > texelFetch(frontDepth, ivec2(gl_FragCoord.xy), 0).r + 1e-6) discard;
    vec3 view = worldPosition - cameraPosition;
    float eye = length(view);
    view /= eye;
    faceNormal = normalize(cross(dFdx(worldPosition), dFdy(worldPosition)));
    if (dot(faceNormal, worldNormal) < 0.0) faceNormal = -faceNormal;
    facePoint = worldPosition;
    // The first two stretches the ray spends inside (segment.frag); the second is
    // unused (-1, -2) where the targets hold the first alone.
    // This fragment is the first stretch's entry: its own distance is exact where
    // the one read back from the depth buffer is not (against 1/sigma_t).
    vec4 inside = texelFetch(insideSegments, ivec2(gl_FragCoord.xy), 0);
    vec3 sum = alongStretch(eye, inside.y, 0.0, view);
    float crossed = max(inside.y - eye, 0.0);
    if (inside.w > inside.z) sum += alongStretch(inside.z, inside.w, crossed, view);
    colour = vec4(albedo * sum, 0.0);
}
