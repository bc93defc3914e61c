#version 450 core
// Single scattering of an optically thick object (SampleScheme::OpticallyThick): light dies
// within a sliver under the surface, thin against its curvature, so the surface
// is a plane there. Along the view ray at distance u the depth is u cos_v and the
// light has come z / cos_l through the medium, so
//   L = int sigma_s p E exp(-sigma_t u cos_v / cos_l) exp(-sigma_t u) du
//     = albedo p E cos_l / (cos_l + cos_v),
// the Lommel-Seeliger law times the phase function, whatever sigma_t is. Index-
// matched boundary, as everywhere in Lucent; blockers lie deeper than the light goes.
in vec3 worldPosition;
in vec3 worldNormal;

#include "gpu_layout.h"
#include "lights.glsl"
#include "phase.glsl"

uniform int lightCount;
uniform vec3 cameraPosition;
uniform vec3 albedo;
uniform float g;               // Henyey-Greenstein mean cosine
uniform sampler2D frontDepth;  // nearest front face of the translucent meshes

out vec4 colour;

void main() {
    // Only the nearest front face is visible; concave meshes draw several per pixel.
    if (gl_FragCoord.z > texelFetch(frontDepth, ivec2(gl_FragCoord.xy), 0).r + 1e-6) discard;
    vec3 n = normalize(worldNormal);
    vec3 toEye = normalize(cameraPosition - worldPosition);
    float cosV = max(dot(n, toEye), 0.0);
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
        float cosL = dot(n, toLight);
        if (cosL <= 0.0) continue;
        sum += henyeyGreenstein(g, dot(-toLight, toEye)) * lights[j].power.rgb * falloff * cosL / (cosL + cosV);
    }
    colour = vec4(albedo * sum, 0.0);
}
