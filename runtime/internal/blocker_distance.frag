#version 450 core
// Blocker shadow maps (runtime/internal/blocker_shadows.h): each blocker fragment writes
// how far along the light's rays it lies; MIN blending keeps the nearest.
in vec3 worldPosition;
in vec3 worldNormal;
uniform vec4 light;  // position, w = 1 (point light), or the direction of travel, w = 0
layout(location = 0) out float lightDistance;

void main() {
    lightDistance = light.w > 0.5 ? distance(worldPosition, light.xyz) : dot(worldPosition, light.xyz);
}
