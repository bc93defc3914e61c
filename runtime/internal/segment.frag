#version 450 core
// Once per pixel and frame: where the pixel's ray is inside the translucent
// objects, in eye distance, stopped by the host's depth.
//  - segment: [t0, t1] from the nearest front face to the farthest back face
//    (t0 > t1 where the host hides the objects; t0 < 0 where the ray misses them);
//  - inside: the first two intervals the ray spends inside, from the peeled
//    entries (front faces) and exits (back faces), so that the air between two
//    parts of a concave object, or between two objects, holds no Gaussian and
//    dims nothing (scatter.frag). Closed meshes alternate entry and exit; the
//    second interval runs from the second entry to the farthest back face.
//    An unused interval is (-1, -2).
#include "gpu_layout.h"

#ifdef ONE_PASS_LAYERS
// depth_layers.frag's array: the fronts, the backs, the farthest back, as bits.
uniform usampler2DArray layers;
float frontLayer(int k, ivec2 pixel) { return uintBitsToFloat(texelFetch(layers, ivec3(pixel, k), 0).r); }
float backLayer(int k, ivec2 pixel) {
    return uintBitsToFloat(texelFetch(layers, ivec3(pixel, kMaxRaySegments + k), 0).r);
}
float farthestBackAt(ivec2 pixel) {
    return uintBitsToFloat(texelFetch(layers, ivec3(pixel, 2 * kMaxRaySegments), 0).r);
}
#else
uniform sampler2D frontLayers[kMaxRaySegments];  // 1st, 2nd, ... nearest front face
uniform sampler2D backLayers[kMaxRaySegments];   // 1st, 2nd, ... nearest back face
uniform sampler2D farthestBack;
float frontLayer(int k, ivec2 pixel) { return texelFetch(frontLayers[k], pixel, 0).r; }
float backLayer(int k, ivec2 pixel) { return texelFetch(backLayers[k], pixel, 0).r; }
float farthestBackAt(ivec2 pixel) { return texelFetch(farthestBack, pixel, 0).r; }
#endif
uniform sampler2D hostDepth;
uniform mat4 inverseProjection;
uniform vec2 viewportSize;
uniform bool cameraInside;  // then the rays start at the eye

layout(location = 0) out vec2 segment;
layout(location = 1) out vec4 inside;

float eyeDistance(float depth, vec2 ndc) {
    vec4 p = inverseProjection * vec4(ndc, 2.0 * depth - 1.0, 1.0);
    return length(p.xyz / p.w);
}

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec2 ndc = gl_FragCoord.xy / viewportSize * 2.0 - 1.0;
#ifdef FIRST_INTERVAL_ONLY
    // FrameTargets::Layers::FirstInterval: the first entry and exit alone (no
    // farthest back face was drawn); segment and the reach are not read.
    float entry = frontLayer(0, pixel), exit = backLayer(0, pixel);
    float host = texelFetch(hostDepth, pixel, 0).r;
    float a = cameraInside ? 0.0 : eyeDistance(entry, ndc);
    float b = min(eyeDistance(exit, ndc), host < 1.0 ? eyeDistance(host, ndc) : 3.4e38);
    bool hit = exit < 1.0 && (cameraInside || entry < 1.0) && a < b;
    inside = vec4(hit ? vec2(a, b) : vec2(-1.0, -2.0), -1.0, -2.0);
    segment = vec2(-1.0, -2.0);
    gl_FragDepth = 0.0;
#else
    float front = frontLayer(0, pixel), back = farthestBackAt(pixel);
    float host = texelFetch(hostDepth, pixel, 0).r;
    float hostT = host < 1.0 ? eyeDistance(host, ndc) : 3.4e38;
    vec2 intervals[kMaxRaySegments];
    for (int k = 0; k < kMaxRaySegments; ++k) intervals[k] = vec2(-1.0, -2.0);
    if (back <= 0.0 || (front >= 1.0 && !cameraInside)) {
        segment = vec2(-1.0, -2.0);
    } else {
        float t0 = cameraInside ? 0.0 : eyeDistance(front, ndc);
        float tEnd = eyeDistance(back, ndc);
        segment = vec2(t0, min(tEnd, hostT));
        // Interval k enters at the k-th front face (camera inside: at the eye, then
        // at the (k-1)-th) and leaves at the k-th back face.
        for (int k = 0; k < kMaxRaySegments; ++k) {
            float entry;
            if (cameraInside) entry = k == 0 ? 0.0 : frontLayer(k - 1, pixel);
            else entry = frontLayer(k, pixel);
            float exit = backLayer(k, pixel);
            if ((k > 0 || !cameraInside) && entry >= 1.0) break;
            if (exit >= 1.0) break;
            float a = (cameraInside && k == 0) ? 0.0 : eyeDistance(entry, ndc);
            float b = k == kMaxRaySegments - 1 ? tEnd : eyeDistance(exit, ndc);
            b = min(b, hostT);
            if (a >= b) break;
            intervals[k] = vec2(a, b);
        }
    }
    inside = vec4(intervals[0], intervals[1]);
    // The depth of the farthest point any interval reaches, 0 where none is
    // inside: the scattering pass's proxies are depth-tested against it
    // (scatter.geom), so that a Gaussian wholly beyond it, or a pixel whose ray
    // misses the objects, costs no fragment shading.
    gl_FragDepth = intervals[0].y > intervals[0].x ? min(back, host) : 0.0;
#endif
}
