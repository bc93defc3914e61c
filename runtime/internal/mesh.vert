#version 450 core
// Translucent meshes for the surface and depth passes (thesis 3.4.1).
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;

uniform mat4 viewProjection;

out vec3 worldPosition;
out vec3 worldNormal;

void main() {
    worldPosition = position;
    worldNormal = normal;
    gl_Position = viewProjection * vec4(position, 1.0);
}
