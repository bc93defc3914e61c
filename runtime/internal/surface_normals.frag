#version 450 core
// Pass 1a (thesis 3.4.1): where the reflected surface term is drawn, the first
// step of drawing it deferred (surface_pass.h). Each pixel keeps the nearest
// front face of an object with a surface: its interpolated normal and the
// object's place in the batch (+1; 0 is no surface), its depth in the target's
// depth buffer.
in vec3 worldPosition;
in vec3 worldNormal;

uniform sampler2D frontDepth;  // nearest front face of the translucent meshes
uniform float slot;

out vec4 normalAndSlot;

void main() {
    // Only the nearest front face of every translucent mesh is seen: one
    // without a surface in front hides one with.
    if (gl_FragCoord.z > texelFetch(frontDepth, ivec2(gl_FragCoord.xy), 0).r + 1e-6) discard;
    normalAndSlot = vec4(normalize(worldNormal), slot + 1.0);
}
