#version 450 core
#include "sample_light.glsl"
// The environment's light times each sample's attenuation, projected onto SH
// (thesis 3.3, eq. 3.4): once per change of the environment, the placements or
// the medium scale. The environment is the directional lights
// [environmentFirst, environmentFirst + environmentCount) of the lights' block,
// drawn from its map by importance (core/environment_map.h), so that
// S_lm = sum_j E_j psi_i(w_j) Y_lm(w_j) estimates the integral of E(w) psi_i(w) Y_lm(w).
// Each frame then reads it at one light's cost (sample_light.glsl, environmentLight).
// The blockers' shadow maps are the point and directional lights' only: the
// environment's light is not dimmed by blockers (SsMethod::limitations).
layout(local_size_x = 64) in;
layout(std430, binding = kBindingEnvironmentSh) writeonly buffer EnvironmentShOut { vec4 projected[]; };
uniform int sampleCount;
uniform int environmentFirst;
uniform int environmentCount;

void main() {
    int i = int(gl_GlobalInvocationID.x);
    if (i >= sampleCount) return;
    int n = environmentBands * environmentBands;
    vec3 s[kEnvironmentShMax];
    for (int k = 0; k < n; ++k) s[k] = vec3(0.0);
    vec3 toward = vec3(0.0);
    float total = 0.0;
    float y[kEnvironmentShMax];
    for (int j = environmentFirst; j < environmentFirst + environmentCount; ++j) {
        vec3 toLight = -lights[j].position.xyz;
        vec3 psi = attenuation(i, toLight);
        vec3 light = lights[j].power.rgb * psi;
        float share = light.r + light.g + light.b;
        if (share <= 0.0) continue;
        environmentBasis(toLight, y);
        for (int k = 0; k < n; ++k) s[k] += light * y[k];
        toward += share * pathGradient(i, toLight, psi.r);
        total += share;
    }
    int base = i * environmentRecords();
    for (int k = 0; k < n; ++k) projected[base + k] = vec4(s[k], 0.0);
    projected[base + n] = vec4(total > 0.0 ? toward / total : vec3(0.0), 0.0);
}
