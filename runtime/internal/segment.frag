#version 450 core
// Once per pixel and frame: where the pixel's ray is inside the translucent
// objects, [t0, t1] in eye distance, from the nearest front face to the farthest
// back face and stopped by the host's depth. (t0 > t1 where the host hides the
// object; t0 < 0 where the ray misses it.)
uniform sampler2D frontDepth;
uniform sampler2D backDepth;
uniform sampler2D hostDepth;
uniform mat4 inverseProjection;
uniform vec2 viewportSize;
uniform bool cameraInside;  // then the rays start at the eye

out vec2 segment;

float eyeDistance(float depth, vec2 ndc) {
    vec4 p = inverseProjection * vec4(ndc, 2.0 * depth - 1.0, 1.0);
    return length(p.xyz / p.w);
}

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    float front = texelFetch(frontDepth, pixel, 0).r, back = texelFetch(backDepth, pixel, 0).r;
    if (back <= 0.0 || (front >= 1.0 && !cameraInside)) {
        segment = vec2(-1.0, -2.0);
        return;
    }
    vec2 ndc = gl_FragCoord.xy / viewportSize * 2.0 - 1.0;
    float t0 = cameraInside ? 0.0 : eyeDistance(front, ndc);
    float t1 = eyeDistance(back, ndc);
    float host = texelFetch(hostDepth, pixel, 0).r;
    if (host < 1.0) t1 = min(t1, eyeDistance(host, ndc));
    segment = vec2(t0, t1);
}
