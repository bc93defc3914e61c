#version 450 core
// EntryDistances (runtime/internal/entry_distances.h): where a light's rays enter
// and leave a closed mesh. Pass 0 keeps, by the depth test, the plane of the
// nearest face facing the light (an entry); pass 1, by MIN blending, the
// distance of the nearest face facing away (an exit); pass 2 the distance of
// the nearest entry beyond that exit, reading pass 1's.
in vec3 worldPosition;
in vec3 worldNormal;
uniform vec4 light;  // position, w = 1 (point light), or the direction of travel, w = 0
uniform int pass;
uniform sampler2DArray exits;  // pass 1's, read in pass 2
uniform int layer;             // the layer drawn
layout(location = 0) out vec4 result;

void main() {
    // Facing from the triangle's own plane, turned outward as its interpolated
    // normal is: a smooth normal near a sharp edge can face the other way.
    vec3 plane = normalize(cross(dFdx(worldPosition), dFdy(worldPosition)));
    if (dot(plane, worldNormal) < 0.0) plane = -plane;
    vec3 travel = light.w > 0.5 ? worldPosition - light.xyz : light.xyz;
    bool entry = dot(plane, travel) < 0.0;
    float d = light.w > 0.5 ? distance(worldPosition, light.xyz) : dot(worldPosition, light.xyz);
    if (pass == 0) {
        // The plane, not the distance: a ray between texel centres meets it
        // exactly, where distances interpolated across a curved face are a
        // fraction of a texel off, many mean free paths in a dense medium.
        if (!entry) discard;
        result = vec4(plane, dot(plane, worldPosition));
    } else if (pass == 1) {
        if (entry) discard;
        result = vec4(d);
    } else {
        float exit = texelFetch(exits, ivec3(ivec2(gl_FragCoord.xy), layer), 0).r;
        if (!entry || d <= exit * (1.0 + 1e-5)) discard;
        result = vec4(d);
    }
}
