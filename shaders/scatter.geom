#version 450 core
// Pass 2: each sample becomes a camera-facing square that covers the projection of
// the sphere where its Gaussian exceeds the cut-off (tighter on screen than the
// thesis's cube of side 2r, and 4 vertices instead of 14).
layout(points) in;
layout(triangle_strip, max_vertices = 4) out;

in VertexOut {
    vec3 viewCentre;
    float width;
    vec3 radiance;
} v[];

out GeometryOut {
    flat vec3 viewCentre;
    flat float width;
    flat vec3 radiance;
} o;

uniform mat4 projection;
uniform float cutoffSigmas;  // sqrt(2 ln(1 / epsilon)): exp(-r^2 / 2 s^2) = epsilon at r = cutoffSigmas * s

void emit(vec4 clip) {
    o.viewCentre = v[0].viewCentre;
    o.width = v[0].width;
    o.radiance = v[0].radiance;
    gl_Position = clip;
    EmitVertex();
}

void main() {
    if (max(v[0].radiance.r, max(v[0].radiance.g, v[0].radiance.b)) <= 0.0) return;
    vec3 c = v[0].viewCentre;
    float r = cutoffSigmas * v[0].width;
    float d = length(c);
    if (d <= r * 1.0001 || c.z > -r) {
        // The camera is inside or the sphere crosses the camera plane: cover the screen.
        emit(vec4(-1, -1, 0, 1));
        emit(vec4(1, -1, 0, 1));
        emit(vec4(-1, 1, 0, 1));
        emit(vec4(1, 1, 0, 1));
        EndPrimitive();
        return;
    }
    // The cone from the eye tangent to the sphere cuts the plane through c normal to
    // c in a circle of radius r d / sqrt(d^2 - r^2); the square holds that circle.
    vec3 axis = c / d;
    vec3 u = normalize(cross(axis, abs(axis.y) < 0.9 ? vec3(0, 1, 0) : vec3(1, 0, 0)));
    vec3 w = cross(axis, u);
    float h = r * d / sqrt(d * d - r * r);
    emit(projection * vec4(c + h * (-u - w), 1.0));
    emit(projection * vec4(c + h * (u - w), 1.0));
    emit(projection * vec4(c + h * (-u + w), 1.0));
    emit(projection * vec4(c + h * (u + w), 1.0));
    EndPrimitive();
}
