#version 450 core
// Copies the host's depth texture, whatever its format, into Lucent's own, so that
// the scattering pass never samples a texture attached to the framebuffer it draws to.
// At a reduced resolution (the scattering's, upsample.frag) each pixel takes the
// source's pixel under its centre.
uniform sampler2D source;
uniform vec2 sourcePerPixel;  // source pixels per pixel drawn, per axis (1: the same resolution)
void main() {
    ivec2 p = min(ivec2(gl_FragCoord.xy * sourcePerPixel), textureSize(source, 0) - 1);
    gl_FragDepth = texelFetch(source, p, 0).r;
}
