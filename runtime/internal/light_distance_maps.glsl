// Included by sample_light.glsl and optically_thick.frag: per light j, how far
// along its rays the nearest of some meshes lies (runtime/internal/blocker_shadows.h):
// layers 6j..6j+5 hold the six 90-degree cube faces around a point light,
// layer 6j one orthographic view along a directional light, and each layer's
// view-projection is in shadowViews.
#include "gpu_layout.h"
#include "lights.glsl"
layout(std430, binding = kBindingShadowViews) readonly buffer ShadowViews { mat4 shadowViews[]; };

// How far along light j's rays x lies, as blocker_distance.frag measures it.
float distanceAlongLight(int j, vec3 x) {
    vec4 l = lights[j].position;
    return l.w > 0.5 ? distance(x, l.xyz) : dot(x, l.xyz);
}

// Where x falls in light j's maps of `size` texels a side: the layer, st in
// texels (centres at half-integers less a half: st = uv size - 0.5) and the
// world size of a texel at x. False where x lies outside every layer.
bool distanceMapTexel(int j, vec3 x, ivec2 size, out int layer, out vec2 st, out float texel) {
    vec4 l = lights[j].position;
    layer = 6 * j;
    if (l.w > 0.5) {
        vec3 d = x - l.xyz, a = abs(d);
        int axis = a.x >= a.y && a.x >= a.z ? 0 : (a.y >= a.z ? 1 : 2);
        layer += 2 * axis + (d[axis] < 0.0 ? 1 : 0);
    }
    mat4 m = shadowViews[layer];
    vec4 clip = m * vec4(x, 1.0);
    st = vec2(0.0);
    texel = 0.0;
    if (clip.w <= 0.0) return false;
    vec2 uv = clip.xy / clip.w * 0.5 + 0.5;
    if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0)))) return false;
    // The map spans 2 / |row 0| at unit distance (point) or in all (directional).
    texel = 2.0 / (float(size.x) * length(vec3(m[0][0], m[1][0], m[2][0])));
    if (l.w > 0.5) texel *= distanceAlongLight(j, x);
    st = uv * vec2(size) - 0.5;
    return true;
}
