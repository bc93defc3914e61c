#version 450 core
// (shaders/sample_light.glsl is inserted here)
// The light each sample receives, for isotropic media, once per change of the
// lights or of the medium scale rather than once per frame.
layout(local_size_x = 64) in;
layout(std430, binding = 3) writeonly buffer ReceivedCache { Received cachedReceived[]; };
uniform int sampleCount;

void main() {
    int i = int(gl_GlobalInvocationID.x);
    if (i >= sampleCount) return;
    cachedReceived[i] = receivedLight(i, vec3(0.0, 0.0, 1.0));
}
