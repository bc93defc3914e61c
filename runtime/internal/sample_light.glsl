// Included by scatter.vert and received.comp: the sample and light buffers, the SH expansion of
// each sample's attenuation, and the light a sample receives.
#include "gpu_layout.h"
layout(std430, binding = kBindingSamples) readonly buffer Samples { Sample samples[]; };
#include "lights.glsl"
#include "phase.glsl"
// The SH coefficients, [sample][channel][coefficient], one float per texel (gpu_samples.h).
uniform samplerBuffer coefficients;
float shAt(int k) { return texelFetch(coefficients, k).r; }

uniform int lightCount;
uniform int shOrder;   // bands, at most 8
uniform int channels;  // 1 (grey sigma_t) or 3
uniform float g;       // Henyey-Greenstein mean cosine
uniform float extinctionScale;  // k: sigma_t and sigma_s times k, so psi becomes psi^k

// The samples are the object's, in its own space; it stands scaled by modelScale,
// rotated by modelRotation, then moved by modelTranslation (placement_uniforms.h).
// Directions rotate into the object's space to read its SH; lengths, and so every
// optical depth, grow by modelScale. The samples were made at preprocessedScale
// (their psi is exp(-tau) at that size, docs/sample-file.md), so psi becomes
// psi^(k modelScale / preprocessedScale).
uniform mat3 modelRotation;
uniform vec3 modelTranslation;
uniform float modelScale;
uniform float preprocessedScale;

vec3 placed(vec3 objectPoint) { return modelTranslation + modelScale * (modelRotation * objectPoint); }
vec3 sampleCentre(int i) { return placed(samples[i].centreWidth.xyz); }
float sampleWidth(int i) { return modelScale * samples[i].centreWidth.w; }
vec3 toObject(vec3 worldDirection) { return worldDirection * modelRotation; }  // the transpose's product
float attenuationExponent() { return extinctionScale * modelScale / preprocessedScale; }

// Blocker shadows (runtime/internal/blocker_shadows.h), for samples whose psi leaves the
// blockers out: the distance along each light's rays to the nearest blocker.
#include "light_distance_maps.glsl"
uniform bool blockerShadows;
uniform sampler2DArray shadowDistances;

// The fraction of light j that reaches x past the blockers. A 2x2 percentage-
// closer filter moves the shadow's edge smoothly between texels; the bias of two
// texels keeps a sample in front of a blocker lit however steeply the blocker's
// surface faces away from the light within one texel.
float blockerVisibility(int j, vec3 x) {
    if (!blockerShadows) return 1.0;
    ivec2 size = textureSize(shadowDistances, 0).xy;
    int layer;
    vec2 st;
    float texel;
    if (!distanceMapTexel(j, x, size, layer, st, texel)) return 1.0;
    float own = distanceAlongLight(j, x);
    float bias = 2.0 * texel;
    ivec2 base = ivec2(floor(st));
    vec2 f = st - vec2(base);
    float lit[4];
    for (int k = 0; k < 4; ++k) {
        ivec2 p = clamp(base + ivec2(k & 1, k >> 1), ivec2(0), size - 1);
        lit[k] = own <= texelFetch(shadowDistances, ivec3(p, layer), 0).r + bias ? 1.0 : 0.0;
    }
    return mix(mix(lit[0], lit[1], f.x), mix(lit[2], lit[3], f.x), f.y);
}
// The optical depth to each light traced on the CPU (runtime/internal/traced_light.h),
// [sample][light], in world units before extinctionScale; w = 1: a blocker is in the way.
// It replaces psi_i's SH and the blocker shadows. TRACED_LIGHT is a program
// variant (SamplePass): behind a uniform, llvmpipe evaluated the SH as well.
layout(std430, binding = kBindingTracedDepths) readonly buffer TracedDepths { vec4 tracedDepths[]; };
// REFRACTED_LIGHT (a program variant, with TRACED_LIGHT): the object's boundary
// refracts, and each depth is followed by where that light arrives from and
// how strongly (traced_light.h, tracedRefractedLight).
#ifdef REFRACTED_LIGHT
const int kTracedRecords = 2;
#else
const int kTracedRecords = 1;
#endif
vec3 tracedTransmittance(int i, int j) {
    vec4 traced = tracedDepths[kTracedRecords * (i * lightCount + j)];
    return traced.w > 0.5 ? vec3(0.0) : exp(-extinctionScale * traced.rgb);
}

uniform float shNormalisation[64];  // sqrt(2) K_lm (K_l0 for m = 0) at index l * l + l + |m|

// Distance, in object units, out of the sample's boundary ball along d (object space) (preprocess/sh_projection.cpp,
// ballExitDistance), negative when d never leaves it.
float ballExitDistance(int sampleIndex, vec3 d) {
    vec4 ball = samples[sampleIndex].ball;
    float cosine = dot(d, ball.xyz), depth = ball.w, curvature = samples[sampleIndex].region.z;
    if (curvature <= 0.0) return cosine > 0.0 ? depth / cosine : -1.0;
    float kd = min(curvature * depth, 1.0);
    float a = (1.0 - kd) * cosine, b = kd * (2.0 - kd);
    float root = sqrt(a * a + b);
    if (a >= 0.0) return a + root > 0.0 ? depth * (2.0 - kd) / (a + root) : -1.0;
    return (root - a) / curvature;
}

// Its share of the ball's transmittance along d at the preprocessed size: the part of psi_i the SH do not hold.
vec3 ballTransmittance(int sampleIndex, vec3 d) {
    float share = samples[sampleIndex].region.w;
    if (samples[sampleIndex].ball.w < 0.0 || share <= 0.0) return vec3(0.0);
    float s = ballExitDistance(sampleIndex, d);
    return s < 0.0 ? vec3(0.0) : share * exp(-samples[sampleIndex].extinction.rgb * (preprocessedScale * s));
}

// psi_i(d) per channel for a world direction d, clamped to the range a transmittance can take: the
// half-space transmittance plus the SH expansion of the rest (real SH with the
// Condon-Shortley phase, as core/spherical_harmonics.cpp) summed on the fly,
// without storing the basis.
vec3 attenuation(int sampleIndex, vec3 worldDirection) {
    vec3 d = toObject(worldDirection);
    int n = shOrder * shOrder;
    int base = sampleIndex * channels * n;
    vec3 psi = vec3(0.0);
    float cm = 1.0, sm = 0.0, qmm = 1.0;
    for (int m = 0; m < shOrder; ++m) {
        float q2 = 0.0, q1 = qmm;
        for (int l = m; l < shOrder; ++l) {
            float q;
            if (l == m) q = qmm;
            else if (l == m + 1) q = d.z * (2.0 * m + 1.0) * qmm;
            else q = ((2.0 * l - 1.0) * d.z * q1 - (l + m - 1.0) * q2) / float(l - m);
            if (l > m) { q2 = q1; q1 = q; }
            float kq = shNormalisation[l * l + l + m] * q;
            int plus = base + l * l + l + m, minus = base + l * l + l - m;
            if (m == 0) {
                psi.r += shAt(plus) * kq;
                if (channels == 3) {
                    psi.g += shAt(plus + n) * kq;
                    psi.b += shAt(plus + 2 * n) * kq;
                }
            } else {
                float c = kq * cm, s = kq * sm;
                psi.r += shAt(plus) * c + shAt(minus) * s;
                if (channels == 3) {
                    psi.g += shAt(plus + n) * c + shAt(minus + n) * s;
                    psi.b += shAt(plus + 2 * n) * c + shAt(minus + 2 * n) * s;
                }
            }
        }
        float c = cm * d.x - sm * d.y, s = cm * d.y + sm * d.x;
        cm = c;
        sm = s;
        qmm *= -(2.0 * m + 1.0);
    }
    if (channels == 1) psi = vec3(psi.r);
    psi = clamp(psi + ballTransmittance(sampleIndex, d), 0.0, 1.0);
    float k = attenuationExponent();
    return k == 1.0 ? psi : pow(psi, vec3(k));
}

// The environment's SH bands for this object (SamplePass::environmentBands), at most kEnvironmentShMaxBands.
uniform int environmentBands;
const int kEnvironmentShMax = kEnvironmentShMaxBands * kEnvironmentShMaxBands;
int environmentRecords() { return environmentBands * environmentBands + 1; }

// The real SH of the first environmentBands bands at the unit vector d, in
// attenuation()'s convention (core/spherical_harmonics.cpp), at l * l + l + m.
void environmentBasis(vec3 d, out float y[kEnvironmentShMax]) {
    float cm = 1.0, sm = 0.0, qmm = 1.0;
    for (int m = 0; m < environmentBands; ++m) {
        float q2 = 0.0, q1 = qmm;
        for (int l = m; l < environmentBands; ++l) {
            float q;
            if (l == m) q = qmm;
            else if (l == m + 1) q = d.z * (2.0 * m + 1.0) * qmm;
            else q = ((2.0 * l - 1.0) * d.z * q1 - (l + m - 1.0) * q2) / float(l - m);
            if (l > m) { q2 = q1; q1 = q; }
            float kq = shNormalisation[l * l + l + m] * q;
            if (m == 0) {
                y[l * l + l] = kq;
            } else {
                y[l * l + l + m] = kq * cm;
                y[l * l + l - m] = kq * sm;
            }
        }
        float c = cm * d.x - sm * d.y, s = cm * d.y + sm * d.x;
        cm = c;
        sm = s;
        qmm *= -(2.0 * m + 1.0);
    }
}

// Minus the gradient of the path length to the boundary along w, the direction
// in which the optical depth towards that light falls fastest, per unit sigma_t.
// Out of the boundary ball, through the point e where w leaves it, it is
// m / (w . m) with m the ball's normal at e: at grazing light the light falls off
// with depth far faster than along w. The part of psi the SH hold has an unknown
// exit, and takes w, the derivative only along w. The two are weighted by their
// share of psi (the log-gradient of a sum).
// w is a world direction; the ball is the object's, so it is met in object space.
vec3 pathGradient(int i, vec3 w, float psi) {
    vec4 ball = samples[i].ball;
    vec3 wo = toObject(w);
    float s = ballExitDistance(i, wo);
    if (ball.w < 0.0 || s < 0.0 || psi <= 0.0) return w;
    // m at e = b + s w: from the ball's centre b + (1/curvature - depth) (-n), or n when flat.
    float curvature = samples[i].region.z;
    vec3 m = curvature > 0.0 ? normalize((1.0 - curvature * ball.w) * ball.xyz + curvature * s * wo) : ball.xyz;
    float cosine = max(dot(wo, m), 0.05);
    float own = ballTransmittance(i, wo).r;
    float k = attenuationExponent();
    if (k != 1.0) own = pow(own, k);
    return mix(w, modelRotation * m / cosine, clamp(own / psi, 0.0, 1.0));
}

// What a sample receives from the lights: the light at its centre, and how it
// changes across the Gaussian (its logarithmic gradient, weighted over the lights
// by their share: the gradient of the log of a sum is that average). Moving
// towards light j by d gains exp(sigma_t d) of transmittance and (1 + 2 d / r_j)
// of irradiance, so the gradient is sigma_t towardLights + falloff.

// The environment's light (ScatteringRenderer::setEnvironment) as each sample
// receives it, projected once onto SH by environment_sh.comp: S_lm, the SH of
// E(w) psi_i(w) over the directions w the light comes from, then the direction
// the light falls off fastest in (pathGradient, averaged by share).
// ENVIRONMENT_SH is a program variant (SamplePass), as TRACED_LIGHT is.
#ifdef ENVIRONMENT_SH
layout(std430, binding = kBindingEnvironmentSh) readonly buffer EnvironmentSh { vec4 environmentSh_[]; };

// The scattered light towards toCamera: the phase function's integral against
// S (thesis eq. 3.4). Funk-Hecke: Henyey-Greenstein's band l is g^l, so the
// integral over w of p(-w . c) S(w) is sum_lm g^l S_lm Y_lm(-c). Exact when
// g = 0; the bands past environmentBands are lost (docs/accuracy.md).
vec3 environmentLight(int i, vec3 toCamera) {
    float y[kEnvironmentShMax];
    environmentBasis(-toCamera, y);
    int base = i * environmentRecords();
    vec3 light = vec3(0.0);
    float band = 1.0;  // g^l
    for (int l = 0; l < environmentBands; ++l) {
        for (int k = l * l; k < (l + 1) * (l + 1); ++k) light += band * y[k] * environmentSh_[base + k].rgb;
        band *= g;
    }
    return max(light, vec3(0.0));
}
#endif

// The light sample i receives, with the phase function towards toCamera (any
// vector when g = 0, where p is the constant 1 / (4 pi)).
Received receivedLight(int i, vec3 toCamera) {
    vec3 centre = sampleCentre(i);
    float width = sampleWidth(i);
    vec3 received = vec3(0.0), toward = vec3(0.0), falloff = vec3(0.0);
    float total = 0.0;
    for (int j = 0; j < lightCount; ++j) {
        vec3 toLight;
        vec3 irradiance = lights[j].power.rgb;
        float inverseDistance = 0.0;
        if (lights[j].position.w > 0.5) {
            toLight = lights[j].position.xyz - centre;
            // Inverse-square falloff (Lucent is physically based), averaged over the
            // Gaussian's core: a light inside or on the object stays finite.
            float d2 = max(dot(toLight, toLight), width * width);
            irradiance *= inverseSquare(j, d2);
            inverseDistance = inversesqrt(d2);
            toLight = length(toLight) > 0.0 ? normalize(toLight) : vec3(0.0, 0.0, 1.0);
            irradiance *= spotFalloff(j, -toLight);
        } else {
            toLight = -lights[j].position.xyz;
        }
#ifdef REFRACTED_LIGHT
        // Bent at the boundary: the light arrives along the refracted ray, with
        // the boundary's transmission and its bundle's focusing instead of 1/d^2.
        vec4 arrival = tracedDepths[2 * (i * lightCount + j) + 1];
        toLight = arrival.xyz;
        irradiance = lights[j].power.rgb * arrival.w;
#endif
#ifdef TRACED_LIGHT
        if (max(irradiance.r, max(irradiance.g, irradiance.b)) <= 0.0) continue;
        vec3 psi = tracedTransmittance(i, j);  // the depth holds the blockers
#else
        irradiance *= blockerVisibility(j, centre);
        if (max(irradiance.r, max(irradiance.g, irradiance.b)) <= 0.0) continue;
        vec3 psi = attenuation(i, toLight);
#endif
        // Phase between the light's propagation (-toLight) and the view's (toCamera).
        vec3 light = henyeyGreenstein(g, dot(-toLight, toCamera)) * irradiance * psi;
        float share = light.r + light.g + light.b;
        received += light;
        toward += share * pathGradient(i, toLight, psi.r);
        falloff += share * 2.0 * inverseDistance * toLight;
        total += share;
    }
#ifdef ENVIRONMENT_SH
    {
        vec3 light = environmentLight(i, toCamera);
        float share = light.r + light.g + light.b;
        received += light;
        toward += share * environmentSh_[(i + 1) * environmentRecords() - 1].xyz;
        total += share;
    }
#endif
    float norm = total > 0.0 ? 1.0 / total : 0.0;
    return Received(vec4(received, 0.0), vec4(toward * norm, 0.0), vec4(falloff * norm, 0.0));
}
