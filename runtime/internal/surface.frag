#version 450 core
// Pass 1 (thesis 3.4.1): the reflected surface term, an energy-normalised Phong
// BRDF times each light's irradiance, exactly as --method reference computes it.
in vec3 worldPosition;
in vec3 worldNormal;

#include "gpu_layout.h"
#include "lights.glsl"
#include "phase.glsl"

uniform int lightCount;
uniform vec3 cameraPosition;
uniform vec3 diffuse;
uniform vec3 specular;
uniform float shininess;
uniform sampler2D frontDepth;  // nearest front face of the translucent meshes

out vec4 colour;

void main() {
    // Only the nearest front face is visible; concave meshes draw several per pixel.
    if (gl_FragCoord.z > texelFetch(frontDepth, ivec2(gl_FragCoord.xy), 0).r + 1e-6) discard;
    vec3 n = normalize(worldNormal);
    vec3 toEye = normalize(cameraPosition - worldPosition);
    vec3 sum = vec3(0.0);
    for (int j = 0; j < lightCount; ++j) {
        vec3 toLight;
        float falloff = 1.0;
        if (lights[j].position.w > 0.5) {
            toLight = lights[j].position.xyz - worldPosition;
            float d2 = dot(toLight, toLight);
            if (d2 <= 0.0) continue;
            toLight *= inversesqrt(d2);
            falloff = spotFalloff(j, -toLight) * inverseSquare(j, d2);
        } else {
            toLight = -lights[j].position.xyz;
        }
        float cosI = dot(n, toLight);
        if (cosI <= 0.0) continue;
        vec3 reflected = 2.0 * cosI * n - toLight;
        float cosR = max(dot(reflected, toEye), 0.0);
        vec3 brdf = diffuse / PI + specular * (shininess + 2.0) / (2.0 * PI) * pow(cosR, shininess);
        sum += brdf * lights[j].power.rgb * falloff * cosI;
    }
    colour = vec4(sum, 0.0);
}
