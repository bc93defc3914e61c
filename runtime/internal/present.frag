#version 450 core
// OffscreenFrame::present: linear radiance times exposure, to sRGB, at an offset in the window.
uniform sampler2D radiance;
uniform float exposure;
uniform ivec2 offset;  // of the frame in the window
out vec4 colour;

vec3 toSrgb(vec3 c) {
    c = clamp(c, 0.0, 1.0);
    return mix(12.92 * c, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(vec3(0.0031308), c));
}

void main() {
    vec3 c = texelFetch(radiance, ivec2(gl_FragCoord.xy) - offset, 0).rgb;
    colour = vec4(toSrgb(max(c, vec3(0.0)) * exposure), 1.0);
}
