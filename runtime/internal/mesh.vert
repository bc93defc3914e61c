#version 450 core
// Translucent meshes for the surface and depth passes (thesis 3.4.1), and the
// blockers: in the object's own space, placed by its model matrix (a similarity,
// runtime/internal/placement_uniforms.h), so normals only rotate.
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;

uniform mat4 viewProjection;
uniform mat4 model;
uniform mat3 modelRotation;

out vec3 worldPosition;
out vec3 worldNormal;

void main() {
    worldPosition = (model * vec4(position, 1.0)).xyz;
    worldNormal = modelRotation * normal;
    gl_Position = viewProjection * vec4(worldPosition, 1.0);
}
