#version 450 core
// (shaders/sample_light.glsl is inserted here)
// Pass 2, per sample and per frame (thesis 3.4.2): the light each sample scatters
// towards the camera, v_i = sigma_s w_i sum_j p(w_j, w_view) E_j psi_i(w_j) psi_i(w_view),
// with psi_i the SH expansion of exp(-tau(b_i, w)). Done once per sample here, not
// once per fragment, so that another light costs one more SH evaluation per sample.
uniform vec3 cameraPosition;
uniform mat4 view;
// With an isotropic phase function the received light does not depend on the
// view: shaders/received.comp computes it when lights change, and frames reuse it.
uniform bool receivedIsCached;
layout(std430, binding = 3) readonly buffer Received { vec4 cachedReceived[]; };

out VertexOut {
    vec3 viewCentre;
    float width;
    vec3 radiance;
} v;

void main() {
    int i = gl_VertexID;
    vec3 centre = samples[i].centreWidth.xyz;
    vec3 toCamera = normalize(cameraPosition - centre);
    vec3 received = receivedIsCached ? cachedReceived[i].rgb : receivedLight(i, toCamera);
    v.radiance = extinctionScale * samples[i].scattering.rgb * received * attenuation(i, toCamera);
    v.viewCentre = (view * vec4(centre, 1.0)).xyz;
    v.width = samples[i].centreWidth.w;
}
