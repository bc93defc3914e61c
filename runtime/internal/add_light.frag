#version 450 core
// The scattering drawn at full resolution into the sample pass's own target
// (whose depth is the pixels' reach, segment.frag), added to the host's
// framebuffer pixel for pixel.
uniform sampler2D light;

out vec4 colour;

void main() {
    vec4 value = texelFetch(light, ivec2(gl_FragCoord.xy), 0);
    if (value.a <= 0.0) discard;  // no Gaussian reached this pixel
    colour = value;
}
