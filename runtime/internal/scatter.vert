#version 450 core
#include "sample_light.glsl"
// Pass 2, per sample and per frame (thesis 3.4.2): the light each sample scatters
// towards the camera, v_i = sigma_s w_i sum_j p(w_j, w_view) E_j psi_i(w_j) psi_i(w_view),
// with psi_i the SH expansion of exp(-tau(b_i, w)). Done once per sample here, not
// once per fragment, so that another light costs one more SH evaluation per sample.
//
// The thesis holds v_i constant under the Gaussian. But inside a medium the light
// falls off exponentially, and Lucent keeps that variation (the Lucent scheme):
// - towards the lights: across the Gaussian the received light is taken as
//   exp(G . (x - b_i)) times its value at the centre, G its logarithmic gradient
//   there (sample_light.glsl);
// - towards the camera: exactly, per pixel. Along a pixel's ray the transmittance
//   to the eye is exp(-sigma_t (t - t0)) from the front face t0; relative to the
//   centre's own ray, whose front face lies viewDepth in front of the centre, it is
//   psi_i(w_view) exp(-sigma_t ((t - t0) - viewDepth)) (scatter.frag).
// A Gaussian times an exponential is a Gaussian again, shifted and scaled, so the
// line integral stays exact. In a homogeneous object, or one of slabs of constant
// density, the fragments need no psi_i(w_view) at all: they attenuate from their
// own front face, exp(-sigma_t (t - t0)) plus what other slabs on the way take,
// exact on convex objects where the SH of a box's or a blocker's edges are not.
// psi_i(w_view) is only used where the density varies smoothly.
uniform vec3 cameraPosition;
uniform vec3 albedo;  // the medium's, at draw time: the samples hold w_i sigma_t (core/sample_set.h)
uniform mat4 view;
// RECEIVED_CACHED (a program variant, SamplePass::scatterProgram): with an
// isotropic phase function the received light does not depend on the view:
// received.comp computes it when lights change, and frames reuse it. A variant,
// not a uniform: llvmpipe evaluated receivedLight for every sample and frame
// behind the uniform's select.
layout(std430, binding = kBindingReceived) readonly buffer ReceivedCache { Received cachedReceived[]; };
uniform bool lightVaries;  // false for the published scheme: v_i constant under the Gaussian
// VIEW_FROM_FRONT (a program variant, SamplePass::scatterProgram): the light varies
// under the Gaussian and sigma_t is constant, or constant in slabs that
// scatter.frag integrates through, so the fragments attenuate from their own
// front face, exactly, and viewDepth is unused.
#ifdef VIEW_FROM_FRONT
const bool viewFromFront = true;
#else
const bool viewFromFront = false;
#endif
uniform mat4 projection;
uniform sampler2D raySegments;  // per pixel [t0, t1] (segment.frag)

out VertexOut {
    vec3 viewCentre;
    vec3 viewImage;    // the mirror image (preprocess/sample_weights.h)
    float width;
    vec3 radiance;
    vec3 gradient[3];  // towards the lights, view space, per channel
    vec3 extinction;
    float viewDepth;   // eye distance from the front face to the centre on the centre's ray; < 0: unknown
    vec2 region;
    vec4 apparent;     // REFRACTED_VIEW: where the centre is seen (apparentCentre)
} v;

#ifdef REFRACTED_VIEW
// REFRACTED_VIEW (a program variant, SamplePass::scatterProgram): the object's
// boundary refracts the view (runtime/internal/refracted_view.h). A sample is
// seen where the pixels' refracted rays pass through it, not where it projects.
uniform sampler2DArray refractedRays;  // per pixel, view space: stretch k's origin (w > 0: it has one), then its direction
uniform int stretch;                   // the stretch this draw integrates along

vec2 windowOf(vec3 p, vec2 size) {
    vec4 clip = projection * vec4(p, 1.0);
    return (clip.xy / clip.w * 0.5 + 0.5) * size;
}

// The point of pixel p's stretch nearest c; w < 0 where the pixel has none.
vec4 nearestOnRay(ivec2 p, vec3 c) {
    ivec2 size = textureSize(refractedRays, 0).xy;
    if (any(lessThan(p, ivec2(0))) || any(greaterThanEqual(p, size))) return vec4(0.0, 0.0, 0.0, -1.0);
    vec4 e = texelFetch(refractedRays, ivec3(p, 2 * stretch), 0);
    if (!(e.w > 0.0)) return vec4(0.0, 0.0, 0.0, -1.0);
    vec3 r = texelFetch(refractedRays, ivec3(p, 2 * stretch + 1), 0).xyz;
    return vec4(e.xyz + max(dot(c - e.xyz, r), 0.0) * r, 1.0);
}

const int kApparentSteps = 8;
const int kApparentSearch = 2;  // the square of pixels searched about where the steps end

// Where the view-space centre c is seen: xy the window position of the pixel
// whose stretch passes nearest c, z how near, w the distance between the
// rays of neighbouring pixels there (the proxy's scale on screen; 0 when no
// neighbour has a ray); its ray's direction in towardsEye. The pixel moves by
// how far its ray's nearest point appears from c on the screen. Through a
// boundary of index n the rays spread by 1/n to 1 of the camera's own, so a
// step leaves at most 1 - 1/n of the error (a flat boundary; more where it is
// strongly curved): eight steps take the error below a pixel.
vec4 apparentCentre(vec3 c, out vec3 towardsEye) {
    vec2 size = vec2(textureSize(refractedRays, 0).xy);
    vec2 q = clamp(windowOf(c, size), vec2(0.5), size - 0.5);
    vec2 best = q;
    float nearest = 1e30;
    for (int k = 0; k < kApparentSteps; ++k) {
        vec4 x = nearestOnRay(ivec2(q), c);
        if (x.w < 0.0) break;
        float miss = distance(x.xyz, c);
        if (miss < nearest) {
            nearest = miss;
            best = floor(q) + 0.5;
        }
        q = clamp(q + windowOf(c, size) - windowOf(x.xyz, size), vec2(0.5), size - 0.5);
    }
    // The steps stop within a pixel or two of the nearest; the pixels around settle it.
    ivec2 around = ivec2(best);
    for (int j = -kApparentSearch; j <= kApparentSearch; ++j)
        for (int i = -kApparentSearch; i <= kApparentSearch; ++i) {
            vec4 x = nearestOnRay(around + ivec2(i, j), c);
            float miss = x.w < 0.0 ? 1e30 : distance(x.xyz, c);
            if (miss < nearest) {
                nearest = miss;
                best = vec2(around + ivec2(i, j)) + 0.5;
            }
        }
    ivec2 p = ivec2(best);
    towardsEye = -texelFetch(refractedRays, ivec3(p, 2 * stretch + 1), 0).xyz;
    vec4 x = nearestOnRay(p, c);
    float spacing = 1e30;
    for (int k = 0; k < 4; ++k) {
        vec4 y = nearestOnRay(p + ivec2(k == 0 ? 1 : (k == 1 ? -1 : 0), k == 2 ? 1 : (k == 3 ? -1 : 0)), c);
        if (y.w >= 0.0 && x.w >= 0.0) spacing = min(spacing, distance(x.xyz, y.xyz));
    }
    if (nearest == 1e30) return vec4(q, 0.0, 0.0);  // no ray found: drawn nowhere
    return vec4(best, nearest, spacing == 1e30 ? 0.0 : spacing);
}
#endif

// |G| s beyond this extrapolates the exponential past where the centre's light
// says anything about it (the light then changes by e^3 within one sigma).
const float kMaxGradientTimesWidth = 3.0;

void main() {
    int i = gl_VertexID;
    vec3 centre = sampleCentre(i);
    float s = sampleWidth(i);
    vec3 toCamera = normalize(cameraPosition - centre);
    v.apparent = vec4(0.0);
#ifdef REFRACTED_VIEW
    {
        vec3 towardsEye;
        v.apparent = apparentCentre((view * vec4(centre, 1.0)).xyz, towardsEye);
        if (v.apparent.w > 0.0) toCamera = normalize(transpose(mat3(view)) * towardsEye);
    }
#endif
#ifdef RECEIVED_CACHED
    Received received = cachedReceived[i];
#else
    Received received = receivedLight(i, toCamera);
#endif
    v.viewCentre = (view * vec4(centre, 1.0)).xyz;
    v.viewImage = (view * vec4(placed(samples[i].image.xyz), 1.0)).xyz;
    v.width = s;
    v.region = samples[i].region.xy;
    v.extinction = extinctionScale * samples[i].extinction.rgb;
    v.viewDepth = -1.0;
    vec4 clip = projection * vec4(v.viewCentre, 1.0);
    if (lightVaries && !viewFromFront && clip.w > 0.0) {
        ivec2 size = textureSize(raySegments, 0);
        vec2 pixel = (clip.xy / clip.w * 0.5 + 0.5) * vec2(size);
        if (all(greaterThanEqual(pixel, vec2(0.0))) && all(lessThan(pixel, vec2(size)))) {
            vec2 segment = texelFetch(raySegments, ivec2(pixel), 0).rg;
            if (segment.x >= 0.0) v.viewDepth = max(length(v.viewCentre) - segment.x, 0.0);
        }
    }
    vec3 towardCamera = viewFromFront ? vec3(1.0) : attenuation(i, toCamera);
    v.radiance = extinctionScale * albedo * samples[i].scattering.rgb * received.light.rgb * towardCamera;
    for (int c = 0; c < 3; ++c) {
        vec3 g = vec3(0.0);
        if (lightVaries) {
            g = v.extinction[c] * received.towardLights.xyz + received.falloff.xyz;
            float reach = length(g) * s;
            if (reach > kMaxGradientTimesWidth) g *= kMaxGradientTimesWidth / reach;
        }
        v.gradient[c] = mat3(view) * g;
    }
}
