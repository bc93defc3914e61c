#version 450 core
// Once per pixel and frame: where the pixel's ray is inside the translucent
// objects, [t0, t1] in eye distance, from the nearest front face to the farthest
// back face and stopped by the host's depth. (t0 > t1 where the ray misses.)
uniform sampler2D frontDepth;
uniform sampler2D backDepth;
uniform sampler2D hostDepth;
uniform mat4 inverseProjection;
uniform vec2 viewportSize;

out vec2 segment;

float eyeDistance(float depth, vec2 ndc) {
    vec4 p = inverseProjection * vec4(ndc, 2.0 * depth - 1.0, 1.0);
    return length(p.xyz / p.w);
}

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    float front = texelFetch(frontDepth, pixel, 0).r;
    if (front >= 1.0) {
        segment = vec2(1.0, -1.0);
        return;
    }
    vec2 ndc = gl_FragCoord.xy / viewportSize * 2.0 - 1.0;
    float t0 = eyeDistance(front, ndc);
    float t1 = eyeDistance(texelFetch(backDepth, pixel, 0).r, ndc);
    float host = texelFetch(hostDepth, pixel, 0).r;
    if (host < 1.0) t1 = min(t1, eyeDistance(host, ndc));
    segment = vec2(t0, t1);
}
