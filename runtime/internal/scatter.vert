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
} v;

// |G| s beyond this extrapolates the exponential past where the centre's light
// says anything about it (the light then changes by e^3 within one sigma).
const float kMaxGradientTimesWidth = 3.0;

void main() {
    int i = gl_VertexID;
    vec3 centre = sampleCentre(i);
    float s = sampleWidth(i);
    vec3 toCamera = normalize(cameraPosition - centre);
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
    v.radiance = extinctionScale * samples[i].scattering.rgb * received.light.rgb * towardCamera;
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
