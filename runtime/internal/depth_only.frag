#version 450 core
// Front and back depth of the translucent meshes: only the depth buffer is written.
void main() {}
