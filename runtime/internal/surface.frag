#version 450 core
// Pass 1b (thesis 3.4.1): the reflected surface term, an energy-normalised Phong
// BRDF times each light's irradiance, exactly as --method reference computes it,
// once per pixel from what surface_normals.frag kept. Shading the meshes'
// fragments instead ran llvmpipe's 4x4 blocks 20% full on the bunny's small
// triangles (docs/runtime.md).
#include "gpu_layout.h"
#include "lights.glsl"
#include "phase.glsl"

uniform int lightCount;
uniform vec3 cameraPosition;
uniform mat4 inverseViewProjection;
uniform vec2 viewportSize;
uniform sampler2D normals;  // normal, slot + 1
uniform sampler2D depths;   // the kept face's window depth
const int kSurfaceBatch = 32;                    // SurfacePass::kBatch
uniform vec4 diffuse[kSurfaceBatch];             // rgb
uniform vec4 specularShininess[kSurfaceBatch];  // rgb, shininess

out vec4 colour;

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec4 kept = texelFetch(normals, pixel, 0);
    if (kept.w < 0.5) discard;
    float z = texelFetch(depths, pixel, 0).r;
    gl_FragDepth = z;  // the host's depth test, as the face itself met it
    vec4 world = inverseViewProjection * vec4(gl_FragCoord.xy / viewportSize * 2.0 - 1.0, 2.0 * z - 1.0, 1.0);
    vec3 worldPosition = world.xyz / world.w;
    int slot = int(kept.w + 0.5) - 1;
    vec3 kd = diffuse[slot].rgb, ks = specularShininess[slot].rgb;
    float shininess = specularShininess[slot].w;
    vec3 n = kept.xyz;
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
        vec3 brdf = kd / PI + ks * (shininess + 2.0) / (2.0 * PI) * pow(cosR, shininess);
        sum += brdf * lights[j].power.rgb * falloff * cosI;
    }
    colour = vec4(sum, 0.0);
}
