// The scene's lights (ScatteringRenderer::setLights), for every program that
// lights something. A uniform block, not a storage buffer: llvmpipe reads a
// storage buffer lane by lane even at an index every lane shares, and reading
// the lights so was a quarter of the surface pass. std140 lays out Light (three vec4) as std430 and C++ do.
#include "gpu_layout.h"
layout(std140, binding = kBindingLights) uniform Lights { Light lights[kMaxLights]; };

// The share of light j's intensity it sends along the unit direction w it
// travels: a spot's cone (KHR_lights_punctual, core/scene.h's spotFalloff), 1 for any other light.
float spotFalloff(int j, vec3 w) {
    vec4 c = lights[j].spot;
    float ramp = clamp(dot(c.xyz, w) + c.w, 0.0, 1.0);
    return ramp * ramp;
}
