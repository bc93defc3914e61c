#version 450 core
// Copies the host's depth texture, whatever its format, into Lucent's own, so that
// the scattering pass never samples a texture attached to the framebuffer it draws to.
uniform sampler2D source;
void main() { gl_FragDepth = texelFetch(source, ivec2(gl_FragCoord.xy), 0).r; }
