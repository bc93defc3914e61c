// The scene's lights (ScatteringRenderer::setLights), for every program that
// lights something. A uniform block, not a storage buffer: llvmpipe reads a
// storage buffer lane by lane even at an index every lane shares, and reading
// the lights so was a quarter of the surface pass. std140 lays out Light (three vec4) as std430 and C++ do.
#include "gpu_layout.h"
layout(std140, binding = kBindingLights) uniform Lights { Light lights[kMaxLights]; };

// What replaces 1 / d^2 for light j at squared distance d2 from its centre: for
// a sphere light of radius R, L_e times its cone's solid angle per unit intensity,
// 2 / (d2 (1 + sqrt(1 - R^2 / d2))) (core/sphere_light.h); nothing inside it.
float inverseSquare(int j, float d2) {
    float r = lights[j].power.w;
    if (r <= 0.0) return 1.0 / d2;
    float s2 = r * r / d2;
    return s2 < 1.0 ? 2.0 / (d2 * (1.0 + sqrt(1.0 - s2))) : 0.0;
}

// The share of light j's intensity it sends along the unit direction w it
// travels: a spot's cone (KHR_lights_punctual, core/scene.h's spotFalloff), 1 for any other light.
float spotFalloff(int j, vec3 w) {
    vec4 c = lights[j].spot;
    float ramp = clamp(dot(c.xyz, w) + c.w, 0.0, 1.0);
    return ramp * ramp;
}
