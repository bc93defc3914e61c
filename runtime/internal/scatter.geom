#version 450 core
// Pass 2: each sample becomes a camera-facing square that covers the projection of
// the sphere where its Gaussian exceeds the cut-off (tighter on screen than the
// thesis's cube of side 2r, and 4 vertices instead of 14). The sphere grows by
// the largest shift of the light's exponential variation (scatter.frag).
// A sample near the boundary of its region gets a second square for its mirror
// image (preprocess/sample_weights.h), which reaches inside only that far.
layout(points) in;
layout(triangle_strip, max_vertices = 8) out;

in VertexOut {
    vec3 viewCentre;
    vec3 viewImage;
    float width;
    vec3 radiance;
    vec3 gradient[3];
    vec3 extinction;
    float viewDepth;
    vec2 region;
} v[];

out GeometryOut {
    flat vec3 viewCentre;    // of this proxy's Gaussian: the sample's or its image's
    flat vec3 anchorOffset;  // that centre minus the sample's, where its light is known
    flat float width;
    flat vec3 radiance;
    flat vec3 gradient[3];
    flat vec3 extinction;
    flat float viewDepth;
    flat vec2 region;
} o;

uniform mat4 projection;
uniform float cutoffSigmas;  // sqrt(2 ln(1 / epsilon)): exp(-r^2 / 2 s^2) = epsilon at r = cutoffSigmas * s
// Projected on the screen a Gaussian is a 2D Gaussian: a fraction epsilon of its
// mass lies beyond the circle of radius cutoffSigmas * s, and the square around
// that circle keeps erf(cutoffSigmas / sqrt 2)^2 of it. The kept part is scaled
// to the whole by the inverse, so the cut-off moves light inwards and loses none.
uniform float keptMassInverse;

// The window depth of the sphere's nearest point (as NDC z), the same over the
// whole proxy: the pass's depth test (GL_LESS against each pixel's reach,
// segment.frag) then rejects the pixels whose ray leaves the objects before it
// meets the sphere, and those that miss the objects. Conservative: along any ray
// the planar depth grows, and no point of the sphere is nearer than this.
float proxyDepth;

void emit(vec3 centre, vec4 clip) {
    o.viewCentre = centre;
    o.anchorOffset = centre - v[0].viewCentre;
    o.width = v[0].width;
    o.radiance = v[0].radiance * keptMassInverse;
    o.gradient = v[0].gradient;
    o.extinction = v[0].extinction;
    o.viewDepth = v[0].viewDepth;
    o.region = v[0].region;
    gl_Position = vec4(clip.xy, proxyDepth * clip.w, clip.w);
    EmitVertex();
}

// A square around the sphere (centre c, radius r) outside which the Gaussian
// centred at gaussian adds nothing.
void proxy(vec3 gaussian, vec3 c, float r) {
    float d = length(c);
    vec4 nearest = projection * vec4(0.0, 0.0, min(c.z + r, 0.0), 1.0);
    proxyDepth = c.z + r < 0.0 ? clamp(nearest.z / nearest.w, -1.0, 1.0) : -1.0;
    if (d <= r * 1.0001 || c.z > -r) {
        // The camera is inside or the sphere crosses the camera plane: cover the screen.
        emit(gaussian, vec4(-1, -1, 0, 1));
        emit(gaussian, vec4(1, -1, 0, 1));
        emit(gaussian, vec4(-1, 1, 0, 1));
        emit(gaussian, vec4(1, 1, 0, 1));
        EndPrimitive();
        return;
    }
    // The cone from the eye tangent to the sphere cuts the plane through c normal to
    // c in a circle of radius r d / sqrt(d^2 - r^2); the square holds that circle.
    // (An octagon, 95% of whose area is the circle's against the square's 79%,
    // took the viewer's frame from 212 to 261 ms, and one triangle, 60%, to 217:
    // llvmpipe shades 4x2 blocks whole and pays per triangle, docs/runtime.md.)
    vec3 axis = c / d;
    vec3 u = normalize(cross(axis, abs(axis.y) < 0.9 ? vec3(0, 1, 0) : vec3(1, 0, 0)));
    vec3 w = cross(axis, u);
    float h = r * d / sqrt(d * d - r * r);
    emit(gaussian, projection * vec4(c + h * (-u - w), 1.0));
    emit(gaussian, projection * vec4(c + h * (u - w), 1.0));
    emit(gaussian, projection * vec4(c + h * (-u + w), 1.0));
    emit(gaussian, projection * vec4(c + h * (u + w), 1.0));
    EndPrimitive();
}

void main() {
    if (max(v[0].radiance.r, max(v[0].radiance.g, v[0].radiance.b)) <= 0.0) return;
    float s = v[0].width;
    // The shift of scatter.frag, G s^2, is at most (|G_light| + sigma_t) s^2.
    // Attenuated from the front face the view's part only ever falls inside, so
    // the light's part alone can carry the integrand beyond the cut-off.
    float shift = 0.0;
    for (int k = 0; k < 3; ++k) {
        float view = v[0].viewDepth >= 0.0 ? v[0].extinction[k] : 0.0;
        shift = max(shift, (length(v[0].gradient[k]) + view) * s * s);
    }
    float r = cutoffSigmas * s + shift;
    proxy(v[0].viewCentre, v[0].viewCentre, r);
    // The boundary lies halfway to the image: past the cut-off, the image adds
    // nothing inside. What it adds lies in the cap of its sphere beyond the
    // boundary plane, at distance a >= d / 2 along the normal and |p|^2 <= r^2 - a^2
    // across it; from the midpoint m that is (a - d / 2)^2 + |p|^2 <= r^2 - d a + d^2 / 4
    // <= r^2 - d^2 / 4. So the cap lies in the sphere of radius sqrt(r^2 - d^2 / 4)
    // about m, whose square is smaller by 1 - d^2 / 4 r^2 in area (by a third on
    // average over the images' distances).
    vec3 toImage = v[0].viewImage - v[0].viewCentre;
    float d = length(toImage);
    if (d > 0.0 && d < 2.0 * cutoffSigmas * s)
        proxy(v[0].viewImage, v[0].viewCentre + 0.5 * toImage, sqrt(max(r * r - 0.25 * d * d, 0.0)));
}
