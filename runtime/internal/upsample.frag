#version 450 core
// The single scattering drawn at a reduced resolution (DrawOptions::scatterScale),
// brought to every pixel: a joint bilateral upsampling (Kopf et al. 2007), as
// real-time volumetric renderers do. A pixel takes its four nearest reduced
// pixels with their bilinear weights, each times how alike its ray's way through
// the objects is to the pixel's own (where it enters and how long it stays
// inside): across a silhouette or a step in depth the light of the other side
// counts for nothing. A pixel none of whose four neighbours is alike (a thin
// part, or an edge narrower than a reduced pixel) takes the likest of the
// sixteen around it.
uniform sampler2D reducedLight;   // RGB: the light scattered towards the eye
uniform sampler2D reducedInside;  // per reduced pixel, its first two intervals inside (segment.frag)
uniform sampler2D fullInside;     // the same per pixel
uniform vec2 reducedPerPixel;     // reduced pixels per pixel, per axis

out vec4 colour;

// Entry distance and the length of the first interval inside: what the
// scattered light depends on most. Only the first: the full-resolution targets
// peel no further when the scattering is reduced (FrameTargets::draw).
vec2 way(vec4 inside) {
    return vec2(inside.x, max(inside.y - inside.x, 0.0));
}

void main() {
    vec4 mine = texelFetch(fullInside, ivec2(gl_FragCoord.xy), 0);
    if (!(mine.y > mine.x)) discard;  // the ray misses the objects, or the host hides them
    vec2 own = way(mine);
    // Alike within 2% of the eye distance, or a fifth of the length inside.
    float tolerance = max(0.02 * own.x, 0.2 * own.y);
    vec2 q = gl_FragCoord.xy * reducedPerPixel - 0.5;
    ivec2 base = ivec2(floor(q));
    vec2 f = q - vec2(base);
    ivec2 last = textureSize(reducedLight, 0) - 1;
    vec3 sum = vec3(0.0);
    float total = 0.0;
    for (int k = 0; k < 4; ++k) {
        ivec2 t = clamp(base + ivec2(k & 1, k >> 1), ivec2(0), last);
        vec4 theirs = texelFetch(reducedInside, t, 0);
        if (!(theirs.y > theirs.x)) continue;
        vec2 d = (way(theirs) - own) / tolerance;
        float w = ((k & 1) == 1 ? f.x : 1.0 - f.x) * ((k >> 1) == 1 ? f.y : 1.0 - f.y) * exp(-dot(d, d));
        sum += w * texelFetch(reducedLight, t, 0).rgb;
        total += w;
    }
    if (total > 1e-4) {
        colour = vec4(sum / total, 0.0);
        return;
    }
    float best = 3.4e38;
    vec3 nearest = vec3(0.0);
    for (int k = 0; k < 16; ++k) {
        ivec2 t = clamp(base + ivec2(k & 3, k >> 2) - 1, ivec2(0), last);
        vec4 theirs = texelFetch(reducedInside, t, 0);
        if (!(theirs.y > theirs.x)) continue;
        vec2 d = way(theirs) - own;
        float distance = dot(d, d);
        if (distance < best) {
            best = distance;
            nearest = texelFetch(reducedLight, t, 0).rgb;
        }
    }
    colour = vec4(nearest, 0.0);
}
