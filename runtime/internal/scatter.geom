#version 450 core
#include "gpu_layout.h"
// Pass 2: each sample becomes a square on the screen, a point sprite or two
// triangles, that covers the projection of the sphere where its Gaussian
// exceeds the cut-off (tighter on screen than the thesis's cube of side 2r). The sphere follows
// the shift of the light's exponential variation (reach, scatter.frag).
// A sample near the boundary of its region gets a second square for its mirror
// image (preprocess/sample_weights.h), which reaches inside only that far.
layout(points) in;
uniform vec2 viewportSize;  // pixels
#ifdef POINT_PROXIES
// POINT_PROXIES (a program variant, SamplePass::scatterProgram): each proxy is
// one point sprite, a square on the screen's axes around the exact bounding box
// of the sphere's projection, instead of two triangles. llvmpipe shades a
// primitive's 4x4 pixel blocks in two 8-wide halves: the blocks along the
// square's diagonal were shaded twice, once for each triangle, and a point is
// set up once. GL clips a point by its centre and limits its size
// (GL_POINT_SIZE_RANGE, 255 pixels on llvmpipe), so the sprites cover the
// bounding box's part inside the viewport in up to kPointProxyTiles^2 points
// centred inside it; SamplePass uses this variant only on targets that many
// points cover.
layout(points, max_vertices = 2 * kPointProxyTiles * kPointProxyTiles) out;
uniform float largestPoint;  // pixels
#else
layout(triangle_strip, max_vertices = 8) out;
#endif

in VertexOut {
    vec3 viewCentre;
    vec3 viewImage;
    float width;
    vec3 radiance;
    vec3 gradient[3];
    vec3 extinction;
    float viewDepth;
    vec2 region;
    vec4 apparent;
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
#ifdef POINT_PROXIES
float pointSize;
#endif

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
#ifdef POINT_PROXIES
    gl_PointSize = pointSize;
#endif
    EmitVertex();
}

#ifdef POINT_PROXIES
// The extent of the sphere's projection along one screen axis (x: k = 0, y: 1),
// in window coordinates. The planes through the eye containing the other screen
// axis and tangent to the sphere, a = m z, meet (c_a - m c_z)^2 = r^2 (1 + m^2);
// the projection maps a / z = m to -P[k][k] m - P[2][k] in NDC.
vec2 projectedExtent(vec3 c, float r, int k) {
    float ca = c[k], cz = c.z;
    float root = r * sqrt(max(ca * ca + cz * cz - r * r, 0.0));
    float denominator = cz * cz - r * r;  // > 0: the sphere lies wholly in front
    vec2 m = vec2(ca * cz - root, ca * cz + root) / denominator;
    vec2 ndc = -projection[k][k] * m - projection[2][k];
    return (vec2(min(ndc.x, ndc.y), max(ndc.x, ndc.y)) * 0.5 + 0.5) * viewportSize[k];
}

// Points centred inside the viewport that cover the box [lo, hi] (window
// coordinates) clipped to it.
void emitPoints(vec3 gaussian, vec2 lo, vec2 hi) {
    lo = max(lo, vec2(0.0));
    hi = min(hi, viewportSize);
    if (any(lessThanEqual(hi, lo))) return;  // wholly off screen
    vec2 size = hi - lo;
    // A sprite covers the pixel centres inside it (left and bottom edges
    // included), as a square covers them: the same pixels along the longer side.
    ivec2 tiles = clamp(ivec2(ceil(size / largestPoint)), ivec2(1), ivec2(kPointProxyTiles));
    vec2 tile = size / vec2(tiles);
    pointSize = max(tile.x, tile.y);
    for (int j = 0; j < tiles.y; ++j)
        for (int i = 0; i < tiles.x; ++i) {
            vec2 centre = lo + (vec2(i, j) + 0.5) * tile;
            emit(gaussian, vec4(centre / viewportSize * 2.0 - 1.0, 0.0, 1.0));
        }
}
#endif

// A square around the sphere (centre c, radius r) outside which the integrand of
// the Gaussian centred at gaussian adds nothing (reach).
void proxy(vec3 gaussian, vec3 c, float r) {
    float d = length(c);
    vec4 nearest = projection * vec4(0.0, 0.0, min(c.z + r, 0.0), 1.0);
    proxyDepth = c.z + r < 0.0 ? clamp(nearest.z / nearest.w, -1.0, 1.0) : -1.0;
    if (d <= r * 1.0001 || c.z > -r * 1.0001) {
        // The camera is inside or the sphere crosses (or touches) the camera
        // plane: cover the screen. Past it, c_z^2 - r^2 >= 2e-4 r^2, which
        // projectedExtent divides by.
#ifdef POINT_PROXIES
        emitPoints(gaussian, vec2(0.0), viewportSize);
        return;
#endif
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
    // made the frame slower, and so did one triangle: llvmpipe shades 4x2 blocks
    // whole and pays per triangle.)
    vec3 axis = c / d;
#ifdef POINT_PROXIES
    vec2 x = projectedExtent(c, r, 0), y = projectedExtent(c, r, 1);
    emitPoints(gaussian, vec2(x.x, y.x), vec2(x.y, y.y));
    return;
#endif
    vec3 u = normalize(cross(axis, abs(axis.y) < 0.9 ? vec3(0, 1, 0) : vec3(1, 0, 0)));
    vec3 w = cross(axis, u);
    float h = r * d / sqrt(d * d - r * r);
    emit(gaussian, projection * vec4(c + h * (-u - w), 1.0));
    emit(gaussian, projection * vec4(c + h * (u - w), 1.0));
    emit(gaussian, projection * vec4(c + h * (-u + w), 1.0));
    emit(gaussian, projection * vec4(c + h * (u + w), 1.0));
    EndPrimitive();
}

// The sphere (xyz centre, w radius) outside which this proxy's integrand adds
// nothing. scatter.frag integrates the Gaussian centred at g times the light's
// exponential variation exp(G' . (x - g)), G' = G - sigma_t dir (sigma_t only
// where the view attenuates relative to the centre's ray; attenuated from each
// pixel's front face, VIEW_FROM_FRONT, the view's part only ever falls inside
// the interval, so the light's part alone can carry the integrand beyond the
// cut-off and viewDepth < 0 leaves it out): that is the same Gaussian
// shifted to g + G' s^2 (and scaled), so its cut-off sphere of radius
// cutoffSigmas s lies about the shifted centre, not about g. The shift differs
// between the channels (their gradients and sigma_t) and, through dir, between
// the pixels: the sphere holds every channel's shifted centre at the centre's
// own ray, and grows by how far sigma_t s^2 dir turns across the proxy (the
// chord between two rays is at most their angle, and asin x <= pi x / 2).
vec4 reach(vec3 g) {
    float s = v[0].width, s2 = s * s;
    vec3 ray = normalize(g);
    vec3 shift[3];
    vec3 mean = vec3(0.0);
    float view = 0.0;
    for (int k = 0; k < 3; ++k) {
        float extinction = v[0].viewDepth >= 0.0 ? v[0].extinction[k] : 0.0;
        shift[k] = (v[0].gradient[k] - extinction * ray) * s2;
        mean += shift[k] / 3.0;
        view = max(view, extinction);
    }
    float spread = 0.0;
    for (int k = 0; k < 3; ++k) spread = max(spread, length(shift[k] - mean));
    vec3 centre = g + mean;
    float r = cutoffSigmas * s + spread;
    float turn = 1.5707964 * (r / max(length(centre), 1e-30) + length(mean) / max(length(g), 1e-30));
    return vec4(centre, r + view * s2 * min(turn, 2.0));
}

#ifdef REFRACTED_VIEW
// Through a refracting boundary (scatter.vert, apparentCentre): a square on the
// screen about where the sample is seen, wide enough that every pixel whose
// stretch passes within the sphere lies inside. The pixels' stretches pass
// apparent.w apart near the sample, so those within the sphere's radius lie
// within that radius over apparent.w of the pixel whose stretch passes
// nearest; the sphere's offset from the centre and that stretch's own miss are
// added on, and the spacing is taken a little narrower (kRaySpreadMargin), as
// it varies across the square. A sample no stretch passes within its sphere
// is seen nowhere. The depth is the near plane's: the stretches' lengths
// inside are not the camera's, so the reach depth says nothing.
const float kRaySpreadMargin = 0.85;
const float kMostMagnified = 3.0;
void refractedProxy(vec3 gaussian, vec4 sphere) {
    vec4 seen = v[0].apparent;
    float radius = distance(sphere.xyz, v[0].viewCentre) + sphere.w;
    if (!(seen.w > 0.0) || seen.z > radius) return;
    float halfSize = (radius + seen.z) / (kRaySpreadMargin * seen.w) + 0.5;
    // Where neighbouring stretches meet (a caustic of the view) their spacing says
    // little: no wider than kMostMagnified times the sphere seen straight.
    float straight = radius * projection[1][1] * 0.5 * viewportSize.y / max(-v[0].viewCentre.z, 1e-6);
    halfSize = min(halfSize, kMostMagnified * straight + 0.5);
    proxyDepth = -1.0;
#ifdef POINT_PROXIES
    emitPoints(gaussian, seen.xy - halfSize, seen.xy + halfSize);
#else
    vec2 lo = max(seen.xy - halfSize, vec2(0.0)) / viewportSize * 2.0 - 1.0;
    vec2 hi = min(seen.xy + halfSize, viewportSize) / viewportSize * 2.0 - 1.0;
    if (any(lessThanEqual(hi, lo))) return;
    emit(gaussian, vec4(lo.x, lo.y, 0.0, 1.0));
    emit(gaussian, vec4(hi.x, lo.y, 0.0, 1.0));
    emit(gaussian, vec4(lo.x, hi.y, 0.0, 1.0));
    emit(gaussian, vec4(hi.x, hi.y, 0.0, 1.0));
    EndPrimitive();
#endif
}
#endif

void main() {
    if (max(v[0].radiance.r, max(v[0].radiance.g, v[0].radiance.b)) <= 0.0) return;
    vec4 sphere = reach(v[0].viewCentre);
#ifdef REFRACTED_VIEW
    refractedProxy(v[0].viewCentre, sphere);
    // The image only where the cap of its sphere on the sample's side reaches (below).
    vec3 offset = v[0].viewImage - v[0].viewCentre;
    if (length(offset) > 0.0) {
        vec4 image = reach(v[0].viewImage);
        vec3 normal = normalize(offset);
        float a = dot(image.xyz - (v[0].viewCentre + 0.5 * offset), normal);
        if (a < image.w)
            refractedProxy(v[0].viewImage, vec4(image.xyz - max(a, 0.0) * normal,
                                                sqrt(image.w * image.w - max(a, 0.0) * max(a, 0.0))));
    }
    return;
#endif
    proxy(v[0].viewCentre, sphere.xyz, sphere.w);
    // The image's integrand counts only on the sample's side of the boundary,
    // which lies halfway to the image (the fragments integrate inside the
    // sample's region alone). Of the image's sphere that keeps the cap beyond
    // the boundary plane seen from its centre, when the centre lies a >= 0
    // past it: the cap lies in the sphere of radius sqrt(r^2 - a^2) about the
    // centre's foot on the plane, whose square is smaller by a^2 / r^2 in area.
    vec3 toImage = v[0].viewImage - v[0].viewCentre;
    float d = length(toImage);
    if (d > 0.0) {
        vec4 image = reach(v[0].viewImage);
        vec3 normal = toImage / d;
        float a = dot(image.xyz - (v[0].viewCentre + 0.5 * toImage), normal);
        if (a < image.w)
            proxy(v[0].viewImage, image.xyz - max(a, 0.0) * normal, sqrt(image.w * image.w - max(a, 0.0) * max(a, 0.0)));
    }
}
