#version 450 core
// Depth peeling (Everitt 2001): the nearest face beyond the previous layer at
// this pixel, for the ray's entries and exits past the first (segment.frag).
uniform sampler2D previousLayer;
void main() {
    if (gl_FragCoord.z <= texelFetch(previousLayer, ivec2(gl_FragCoord.xy), 0).r) discard;
}
