#version 450 core
// Pass 2 (thesis 3.4.2, eq. 3.4): the Gaussian of one sample integrated exactly
// (erf) along this pixel's ray over the part of the ray inside the object (from
// the front face to the farthest back face), stopped by the host's opaque geometry.
in GeometryOut {
    flat vec3 viewCentre;
    flat float width;
    flat vec3 radiance;
} f;

uniform sampler2D raySegments;  // per pixel [t0, t1] inside the objects (shaders/segment.frag)
uniform vec4 pixelToView;       // view-space ray through a pixel: (x sx + ox, y sy + oy, -1)
uniform float discardBelow;     // diagnostics only (render benchmark): 0 in normal use

out vec4 colour;

// erfc for x >= 0: Abramowitz and Stegun 7.1.26 (absolute error < 1.5e-7), written
// as a product with exp(-x^2) so that it keeps its relative accuracy in the tail.
float erfcPositive(float x) {
    float t = 1.0 / (1.0 + 0.3275911 * x);
    float poly = t * (0.254829592 + t * (-0.284496736 + t * (1.421413741 + t * (-1.453152027 + t * 1.061405429))));
    return poly * exp(-x * x);
}

// erf(b) - erf(a) for a <= b, without cancellation when both lie in one tail.
float erfDifference(float a, float b) {
    if (a >= 0.0) return erfcPositive(a) - erfcPositive(b);
    if (b <= 0.0) return erfcPositive(-b) - erfcPositive(-a);
    return 2.0 - erfcPositive(-a) - erfcPositive(b);
}

void main() {
    vec2 segment = texelFetch(raySegments, ivec2(gl_FragCoord.xy), 0).rg;
    float t0 = segment.x, t1 = segment.y;
    if (t1 <= t0) discard;  // the ray misses the object, or the host hides it
    vec3 dir = normalize(vec3(gl_FragCoord.xy * pixelToView.xy + pixelToView.zw, -1.0));

    float s = f.width;
    float tc = dot(dir, f.viewCentre);
    float h2 = max(dot(f.viewCentre, f.viewCentre) - tc * tc, 0.0);
    float k = 1.0 / (sqrt(2.0) * s);
    // int_t0^t1 exp(-|o + t dir - c|^2 / (2 s^2)) dt
    float integral = s * sqrt(0.5 * 3.14159265358979) * exp(-0.5 * h2 / (s * s)) * erfDifference((t0 - tc) * k, (t1 - tc) * k);
    // The largest line integral of this Gaussian is s sqrt(2 pi).
    if (integral < discardBelow * s * sqrt(2.0 * 3.14159265358979)) discard;
    colour = vec4(f.radiance * max(integral, 0.0), 1.0);
}
