#version 450 core
// Pass 2 (thesis 3.4.2, eq. 3.4): the Gaussian of one sample integrated exactly
// (erf) along this pixel's ray over the interval inside the objects nearest its
// centre (of the first two, segment.frag: the air between two parts of a
// concave object holds nothing and dims nothing), stopped by the host's opaque
// geometry and the object's blockers, and clipped to the sample's density slab.
#include "phase.glsl"
in GeometryOut {
    flat vec3 viewCentre;    // of this Gaussian: the sample's or its mirror image's
    flat vec3 anchorOffset;  // that centre minus the sample's, where the light is known
    flat float width;
    flat vec3 radiance;
    flat vec3 gradient[3];  // logarithmic gradient of the light per channel (scatter.vert)
    flat vec3 extinction;
    flat float viewDepth;   // < 0: the published scheme, or the centre is off screen
    flat vec2 region;
} f;

uniform sampler2D insideSegments;  // per pixel, the first two intervals inside the objects (segment.frag)
uniform vec4 pixelToView;       // view-space ray through a pixel: (x sx + ox, y sy + oy, -1)
// The density slabs are the object's: met with the camera and the ray's direction
// in its own space, the direction divided by the object's scale so that the ray's
// parameter stays the view's distance (runtime/internal/placement_uniforms.h).
uniform vec3 objectCamera;
uniform mat3 viewToObject;
// Program variants (SamplePass::scatterProgram), as llvmpipe runs the body of an
// if on a uniform whether it is taken or not (each of the two below cost a
// tenth of the frame untaken; docs/runtime.md, Speed):
// - SAMPLE_REGIONS: the samples belong to regions along an axis (density slabs,
//   preprocess/sample_weights.h), and each Gaussian is clipped to its own;
// - VIEW_FROM_FRONT: attenuate from this pixel's front face (scatter.vert),
//   otherwise from the centre's own ray where viewDepth >= 0;
// - ONE_CHANNEL: sigma_t is grey, and one integral serves the three channels.
#ifdef SAMPLE_REGIONS
uniform int regionAxis;         // 0, 1 or 2
#endif
#ifdef COUNT_USEFUL_FRAGMENTS
uniform float discardBelow;     // diagnostics only (the render benchmark's useful fragments)
#endif
#ifdef REFRACTED_VIEW
// REFRACTED_VIEW (a program variant): the object's boundary refracts, and each
// pixel's ray goes on inside along its refracted direction, from where the
// camera's ray enters (runtime/internal/refracted_view.h), in view space.
// Stretch k of a pixel's ray (refracted_view.h): layer 2k its origin (w: the
// share of the pixel's radiance it carries out, 0: none), 2k + 1 its direction
// (w: its length inside). This draw integrates along stretch `stretch`.
uniform sampler2DArray refractedRays;
uniform int stretch;
#endif
#ifdef DENSITY_SLABS
// The density slabs along regionAxis (runtime/scattering_pass.h), when sigma_t is
// constant in each: [lo, hi] and sigma_t. Compiled only into the program for
// objects that have them: on llvmpipe the loop alone, never run, doubled the
// frame time of every other object.
uniform int slabCount;
uniform vec4 slabBounds[16];
uniform vec4 slabExtinction[16];
#endif

out vec4 colour;

// erfc(x) exp(x^2) for x >= 0: Abramowitz and Stegun 7.1.26 (absolute error of
// erfc < 1.5e-7). Kept apart from exp(-x^2) so that callers can fold that factor
// into other exponents and nothing overflows or underflows on the way.
float erfcScaled(float x) {
    float t = 1.0 / (1.0 + 0.3275911 * x);
    return t * (0.254829592 + t * (-0.284496736 + t * (1.421413741 + t * (-1.453152027 + t * 1.061405429))));
}

// int_t0^t1 exp(logAmplitude - |t dir - c|^2 / (2 s^2)) dt. Every factor that can
// overflow (the amplitude) or underflow (the erfc tails, the distance to the ray)
// is summed in one exponent first; tails subtract without cancellation.
float gaussianSegment(vec3 c, float s, float logAmplitude, vec3 dir, float t0, float t1) {
    float tc = dot(dir, c);
    float h2 = max(dot(c, c) - tc * tc, 0.0);
    float k = 1.0 / (sqrt(2.0) * s);
    float a = (t0 - tc) * k, b = (t1 - tc) * k;
    float e = logAmplitude - 0.5 * h2 / (s * s);
    // With E(x) = exp(e) erfc(|x|): E(a) - E(b) when the interval lies past the
    // centre (a >= 0), E(b) - E(a) when before it (b <= 0), and 2 exp(e) - E(a) - E(b)
    // when it holds it (there exp(e) stops at e^80). One erfc per end chosen by
    // selects: llvmpipe runs every branch of an if, and three of them cost six.
    bool holds = a < 0.0 && b > 0.0;
    float ee = holds ? min(e, 80.0) : e;
    float ea = erfcScaled(abs(a)) * exp(ee - a * a), eb = erfcScaled(abs(b)) * exp(ee - b * b);
    float value = a >= 0.0 ? ea - eb : (b <= 0.0 ? eb - ea : 2.0 * exp(ee) - ea - eb);
    return s * sqrt(0.5 * PI) * max(value, 0.0);
}

// The sample's light along this pixel's ray x = t dir, on the Gaussian centred at
// c (the sample's centre b, or its image): exp(G . (x - b)) towards the lights,
// times the transmittance to the eye. From this pixel's front face t0 it is
// exp(-sigma_t (t - t0)) (VIEW_FROM_FRONT), or relative to the centre's own,
// exp(-sigma_t ((t - t0) - viewDepth)). Gathered as exp(G' . (x - c)) times
// exp(G . (c - b) - sigma_t (dir . c - t0) [+ sigma_t viewDepth]), G' = G - sigma_t dir;
// and a Gaussian times exp(G' . (x - c)) is exp(|G'|^2 s^2 / 2) times the Gaussian
// centred at c + G' s^2. Every exponent is summed before any exp (gaussianSegment).
// Also gives the shifted centre (the benchmark's useful fragments).
// The ray starts at the view's origin; centre is the Gaussian's relative to it.
float shiftedSegment(vec3 centre, vec3 gradient, float extinction, vec3 dir, float front, float t0, float t1,
                     float logOffset, out vec3 shifted) {
    float s2 = f.width * f.width;
    float logScale = dot(gradient, f.anchorOffset) + logOffset;
#ifdef VIEW_FROM_FRONT
    logScale -= extinction * (dot(dir, centre) - front);
    gradient -= extinction * dir;
#else
    if (f.viewDepth >= 0.0) {
        // Where the front face jumps (a concave object's silhouette in front of
        // another part of it) this pixel's front says nothing about the centre's
        // ray: beyond two widths, or a factor e^2, the correction stops growing.
        float shift = f.viewDepth - (dot(dir, centre - f.anchorOffset) - front);
        float limit = min(2.0 * f.width, 2.0 / max(extinction, 1e-30));
        logScale += extinction * (clamp(shift, -limit, limit) - dot(dir, f.anchorOffset));
        gradient -= extinction * dir;
    }
#endif
    shifted = centre + gradient * s2;
    return gaussianSegment(shifted, f.width, logScale + 0.5 * dot(gradient, gradient) * s2, dir, t0, t1);
}

// The ray's parameter interval inside [lo, hi] along regionAxis.
vec2 slabInterval(vec2 bounds, float origin, float direction) {
    if (abs(direction) < 1e-20) return origin >= bounds.x && origin <= bounds.y ? vec2(-1e30, 1e30) : vec2(1e30, -1e30);
    float ta = (bounds.x - origin) / direction, tb = (bounds.y - origin) / direction;
    return vec2(min(ta, tb), max(ta, tb));
}

#ifdef DENSITY_SLABS
// The optical depth from the front face to where the ray enters the sample's
// slab, less the sample's own sigma_t over that distance: what the other slabs
// take beyond what exp(-sigma_t (t - t0)) assumes (0 in a single slab).
vec3 otherSlabsDepth(float origin, float direction, float front, float entry) {
    vec3 depth = vec3(0.0);
    for (int k = 0; k < slabCount; ++k) {
        vec2 span = slabInterval(slabBounds[k].xy, origin, direction);
        float inside = min(entry, span.y) - max(front, span.x);
        if (inside > 0.0) depth += (slabExtinction[k].rgb - f.extinction) * inside;
    }
    return depth;
}
#endif

// The stretch of this pixel's ray the Gaussian is integrated over: the ray
// origin + t dir for t in [t0, t1], attenuated towards the eye from t = front,
// where it entered the objects at t = firstEntry; weight: the share of its
// radiance that reaches the eye. False: the Gaussian adds nothing here.
struct Stretch {
    vec3 origin, dir;
    float front, firstEntry, t0, t1, weight;
};

#ifdef REFRACTED_VIEW
bool stretchAt(ivec2 pixel, out Stretch r) {
    vec4 origin = texelFetch(refractedRays, ivec3(pixel, 2 * stretch), 0);
    if (!(origin.w > 0.0)) return false;
    // This object must be the first thing the camera's ray meets: not hidden by
    // the host's geometry, nor behind another object (refracted_view.h).
    vec4 inside = texelFetch(insideSegments, pixel, 0);
    float entry = length(texelFetch(refractedRays, ivec3(pixel, 0), 0).xyz);
    if (!(inside.y > inside.x) || inside.x < entry * (1.0 - 1e-3)) return false;
    // Attenuated towards the eye over the stretches before this one too.
    float before = 0.0;
    for (int k = 0; k < stretch; ++k) before += texelFetch(refractedRays, ivec3(pixel, 2 * k + 1), 0).w;
    vec4 direction = texelFetch(refractedRays, ivec3(pixel, 2 * stretch + 1), 0);
    r = Stretch(origin.xyz, direction.xyz, -before, 0.0, 0.0, direction.w, origin.w);
    return true;
}
#else
bool stretchAt(ivec2 pixel, out Stretch r) {
    vec4 inside = texelFetch(insideSegments, pixel, 0);
    vec3 dir = normalize(vec3(gl_FragCoord.xy * pixelToView.xy + pixelToView.zw, -1.0));
    // The interval inside the objects nearest the Gaussian's centre along the ray:
    // a Gaussian is narrow next to the parts of an object, so it is integrated over
    // that interval alone, attenuated by the length inside before it (the air
    // between two parts holds nothing and dims nothing). Chosen by a select, not a
    // branch: llvmpipe runs every branch of a fragment shader, and integrating
    // each of four intervals doubled the frame.
    float tc = dot(dir, f.viewCentre);
    bool second = inside.w > inside.z &&
                  max(max(inside.z - tc, tc - inside.w), 0.0) < max(max(inside.x - tc, tc - inside.y), 0.0);
    float a = second ? inside.z : inside.x, b = second ? inside.w : inside.y;
    float before = second ? inside.y - inside.x : 0.0;
    r = Stretch(vec3(0.0), dir, a - before, inside.x, a, b, 1.0);
    return b > a;  // otherwise the ray misses the objects, or the host hides them
}
#endif

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    Stretch ray;
    if (!stretchAt(pixel, ray)) discard;
    vec3 dir = ray.dir;
    float front = ray.front;
    float t0 = ray.t0, t1 = ray.t1;
    vec3 slabsBefore = vec3(0.0);
#ifdef SAMPLE_REGIONS
    {
        // The part of the ray inside the sample's density slab.
        float o = (objectCamera + viewToObject * ray.origin)[regionAxis], d = (viewToObject * dir)[regionAxis];
        vec2 span = slabInterval(f.region, o, d);
        t0 = max(t0, span.x);
        t1 = min(t1, span.y);
#ifdef DENSITY_SLABS
        // From the first entry: across the air between parts too (a concave object
        // of slabs is not exact here).
#ifdef VIEW_FROM_FRONT
        if (t1 > t0) slabsBefore = otherSlabsDepth(o, d, ray.firstEntry, t0);
#endif
#endif
    }
#endif
    if (t1 <= t0) discard;  // the interval misses the sample's slab
    vec3 centre = f.viewCentre - ray.origin;

    vec3 integral;
    vec3 shifted[3];
    integral.r = shiftedSegment(centre, f.gradient[0], f.extinction.r, dir, front, t0, t1, -slabsBefore.r, shifted[0]);
#ifdef ONE_CHANNEL
    integral.gb = integral.rr;
    shifted[1] = shifted[2] = shifted[0];
#else
    integral.g = shiftedSegment(centre, f.gradient[1], f.extinction.g, dir, front, t0, t1, -slabsBefore.g, shifted[1]);
    integral.b = shiftedSegment(centre, f.gradient[2], f.extinction.b, dir, front, t0, t1, -slabsBefore.b, shifted[2]);
#endif
#ifdef COUNT_USEFUL_FRAGMENTS
    // Useful: some channel's integrand, the Gaussian shifted by the light's
    // variation, has a line integral here above the cut-off of its largest,
    // s sqrt(2 pi) at unit amplitude.
    float largest = 0.0;
    for (int k = 0; k < 3; ++k) largest = max(largest, gaussianSegment(shifted[k], f.width, 0.0, dir, t0, t1));
    if (largest < discardBelow * f.width * sqrt(2.0 * PI)) discard;
#endif
    colour = vec4(f.radiance * integral * ray.weight, 1.0);
}
