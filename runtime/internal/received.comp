#version 450 core
#include "sample_light.glsl"
// The light each sample receives, for isotropic media, once per change of the
// lights or of the medium scale rather than once per frame.
layout(local_size_x = 64) in;
layout(std430, binding = kBindingReceived) writeonly buffer ReceivedCache { Received cachedReceived[]; };
uniform int sampleCount;

void main() {
    int i = int(gl_GlobalInvocationID.x);
    if (i >= sampleCount) return;
    cachedReceived[i] = receivedLight(i, vec3(0.0, 0.0, 1.0));
}
