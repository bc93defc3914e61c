#version 450 core
// Single scattering of an optically thick object (SampleScheme::OpticallyThick,
// runtime/internal/thick_pass.h): light dies within a sliver under the surface,
// thinner than the samples could resolve, so each pixel integrates its own view
// ray instead. Along the ray from the nearest front face, at distance u,
//   L = sum_j int sigma_s p_j E_j exp(-sigma_t (d_j(u) + u)) du,
// where d_j(u) is how far light j has come through the medium, read from maps
// of the mesh seen from the light (entry_distances.h). Under a flat face lit at
// cos_l and seen at cos_v, d_j = u cos_v / cos_l and the integral is the
// Lommel-Seeliger law albedo p E cos_l / (cos_l + cos_v) whatever sigma_t is.
// The maps keep what that plane leaves out: light entering one face and
// leaving through the face beside it along an edge, light through a part
// thinner than the light's reach and the air behind it into the next part, and
// a face lit from behind. Index-matched boundary, as everywhere in the closed
// form; blockers lie deeper than the light goes.
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
uniform sampler2D insideSegments;        // per pixel, the first two intervals inside them (segment.frag)
// Per light (entry_distances.h): the plane of its nearest entry into the mesh,
// the distance of the exit after it and of the entry after that.
uniform sampler2DArray entryPlanes;
uniform sampler2DArray entryExits;
uniform sampler2DArray nextEntries;

out vec4 colour;

// Steps along the ray. On each, the light sigma_s p E and the optical depth
// d_j + u are taken as linear and their product with exp(-(d_j + u))
// integrated exactly (stepIntegral), so a flat face lit by a distant light is
// exact with any number; the steps resolve edges and thin parts.
const int kSteps = 32;
// The ray is followed until the view's transmittance falls to e^-9 (1.2e-4).
const float kViewDepth = 9.0;

// How far light reaching distance s along its ray has come through the medium,
// from one texel's entries and exit: inside from the nearest entry e1 to the
// exit x1 and beyond the next entry (from the light itself to x1 when x1 comes
// first: the light stands inside). Negative where that texel's ray is in the
// air at s, within a tolerance: it passes beside x, not through it.
float mediumBefore(float s, float e1, float x1, ivec3 texel, float tolerance) {
    if (x1 >= s) return clamp(s - (x1 < e1 ? 0.0 : e1), 0.0, s);
    float start = x1 < e1 ? 0.0 : e1;
    float next = x1 < e1 ? e1 : texelFetch(nextEntries, texel, 0).r;  // fetched only past the exit
    if (s > x1 + tolerance && s < next - tolerance) return -1.0;
    return max(x1 - start, 0.0) + max(s - next, 0.0);
}

// Where light j's ray through x, travelling along the unit travel, meets the
// entry plane p (outward normal, and its dot product with the plane's points),
// in distance along the light; false where the ray runs along the plane.
bool entryAlong(int j, vec3 x, float s, vec3 travel, vec4 p, out float e) {
    vec4 l = lights[j].position;
    float facing = dot(p.xyz, travel);
    e = 0.0;
    if (!(facing < -1e-3)) return false;
    e = l.w > 0.5 ? (p.w - dot(p.xyz, l.xyz)) / facing : s + (p.w - dot(p.xyz, x)) / facing;
    return true;
}

// The fragment's own face (outward normal, a point), set by main.
vec3 faceNormal;
vec3 facePoint;

// Light j's distance through the medium to x, bilinear over the four texels
// of its maps about x. Each texel's entry is where x's own ray meets that
// texel's plane, exact on a flat face between texel centres; a texel whose
// ray is in the air at x's distance passes beside x and is left out (near an
// edge, where the neighbouring rays leave early). Where the light enters
// through the fragment's own face, the texels may be its neighbours' (the
// facets of a curved mesh, a face seen edge-on from the light): their planes
// put the entry up to a texel's size off along the face, that over cos_l along
// the light, many mean free paths in a dense medium. There the own face's
// plane gives the length when it is the shorter by less than that; by more,
// or where a texel's ray left the medium before x (another part in the way),
// the maps tell (an inner corner, a dimple).
float throughMedium(int j, vec3 x, out bool underOwnFace) {
    ivec2 size = textureSize(entryPlanes, 0).xy;
    int layer;
    vec2 st;
    float texel;
    underOwnFace = false;
    if (!distanceMapTexel(j, x, size, layer, st, texel)) return 0.0;
    float s = distanceAlongLight(j, x);
    vec4 l = lights[j].position;
    vec3 travel = l.w > 0.5 ? normalize(x - l.xyz) : l.xyz;
    ivec2 base = ivec2(floor(st));
    vec2 f = st - vec2(base);
    float sum = 0.0, weight = 0.0;
    bool leftBefore = false;
    for (int k = 0; k < 4; ++k) {
        ivec3 p = ivec3(clamp(base + ivec2(k & 1, k >> 1), ivec2(0), size - 1), layer);
        float x1 = texelFetch(entryExits, p, 0).r;
        float e1 = 3.0e38;
        vec4 plane = texelFetch(entryPlanes, p, 0);
        if (plane.xyz != vec3(0.0) && !entryAlong(j, x, s, travel, plane, e1)) continue;
        if (min(e1, x1) > 1e37) continue;  // a texel the mesh misses says nothing of x
        float medium = mediumBefore(s, e1, x1, p, 2.0 * texel);
        if (medium < 0.0) continue;
        leftBefore = leftBefore || x1 < s - 2.0 * texel;
        float w = ((k & 1) != 0 ? f.x : 1.0 - f.x) * ((k >> 1) != 0 ? f.y : 1.0 - f.y);
        sum += w * medium;
        weight += w;
    }
    float d = weight > 0.0 ? sum / weight : 0.0;
    float cosL = -dot(faceNormal, travel);
    float own;
    if (!leftBefore && entryAlong(j, x, s, travel, vec4(faceNormal, dot(faceNormal, facePoint)), own) &&
        d - (s - own) < 2.0 * texel / max(cosL, 0.05)) {
        underOwnFace = s - own <= d + 0.01 * texel;
        d = min(d, max(s - own, 0.0));
    }
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

// int f exp(-t) over a step of length h on which both f and the optical depth t
// run linearly, f from f0 to f1 and t from a to b, per channel, exactly:
// h e^-a (f0 (E - G) + f1 G) with d = b - a, E = (1 - e^-d) / d and
// G = (1 - e^-d) / d^2 - e^-d / d (1 and 1/2 as d -> 0: the trapezoid).
vec3 stepIntegral(vec3 f0, vec3 f1, vec3 a, vec3 b, float h) {
    vec3 d = b - a;
    vec3 decay = exp(-d);
    vec3 e = (1.0 - decay) / d;
    vec3 g = (e - decay) / d;
    bvec3 small = lessThan(abs(d), vec3(1e-2));
    e = mix(e, 1.0 - d * (0.5 - d / 6.0), small);
    g = mix(g, 0.5 - d * (1.0 / 3.0 - d / 8.0), small);
    return h * exp(-a) * (f0 * (e - g) + f1 * g);
}

// The light scattered toward the eye along the stretch [a, b] of the view ray
// (eye distances), dimmed by the medium crossed on the way before a (a length).
// Where the light enters through the pixel's own face at the stretch's ends
// and middle, and its way there is linear, it is linear all along (a convex
// object's is the least over its faces' planes, and here one plane gives it
// at three points) and two steps are exact: most pixels of a densely lit
// face. Elsewhere (an edge, a thin part, a face lit from behind) kSteps.
vec3 alongStretch(float a, float b, float before, vec3 view) {
    float reach = min(b - a, kViewDepth / max(min(extinction.r, min(extinction.g, extinction.b)), 1e-30) - before);
    if (!(reach > 0.0)) return vec3(0.0);
    vec3 sum = vec3(0.0);
    for (int j = 0; j < lightCount; ++j) {
        vec3 x = cameraPosition + a * view;
        bool first, middle, last;
        float d0 = throughMedium(j, x, first);
        float dMiddle = throughMedium(j, x + 0.5 * reach * view, middle);
        float d1 = throughMedium(j, x + reach * view, last);
        bool linear = abs(dMiddle - 0.5 * (d0 + d1)) < 1e-3 * reach;
        int steps = first && middle && last && linear ? 2 : kSteps;
        float h = reach / float(steps);
        vec3 fBefore = scatteredAt(j, x, view);
        vec3 depthBefore = extinction * (d0 + before);
        for (int k = 1; k <= steps; ++k) {
            float u = h * float(k);
            x = cameraPosition + (a + u) * view;
            bool unused;
            float d = steps == 2 ? (k == 1 ? dMiddle : d1) : throughMedium(j, x, unused);
            vec3 fAfter = scatteredAt(j, x, view);
            vec3 depthAfter = extinction * (d + before + u);
            sum += extinction * stepIntegral(fBefore, fAfter, depthBefore, depthAfter, h);
            fBefore = fAfter;
            depthBefore = depthAfter;
        }
    }
    return sum;
}

void main() {
    // The face's own plane, outward as its interpolated normal is (a smooth
    // normal near a sharp edge can lean past the face); derivatives before any discard.
    faceNormal = normalize(cross(dFdx(worldPosition), dFdy(worldPosition)));
    if (dot(faceNormal, worldNormal) < 0.0) faceNormal = -faceNormal;
    facePoint = worldPosition;
    // Only the nearest front face is visible; concave meshes draw several per pixel.
    if (gl_FragCoord.z > texelFetch(frontDepth, ivec2(gl_FragCoord.xy), 0).r + 1e-6) discard;
    vec3 view = worldPosition - cameraPosition;
    float eye = length(view);
    view /= eye;
    // The first two stretches the ray spends inside (segment.frag). This fragment
    // is the first's entry: its own distance is exact where the one read back
    // from the depth buffer is not (against 1/sigma_t).
    vec4 inside = texelFetch(insideSegments, ivec2(gl_FragCoord.xy), 0);
    vec3 sum = alongStretch(eye, inside.y, 0.0, view);
    float crossed = max(inside.y - eye, 0.0);
    if (inside.w > inside.z) sum += alongStretch(inside.z, inside.w, crossed, view);
    colour = vec4(albedo * sum, 0.0);
}
