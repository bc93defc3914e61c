#version 450 core
// Pass 2 (thesis 3.4.2, eq. 3.4): the Gaussian of one sample integrated exactly
// (erf) along this pixel's ray over the part of the ray inside the object (from
// the front face to the farthest back face), stopped by the host's opaque geometry.
in GeometryOut {
    flat vec3 viewCentre;
    flat float width;
    flat vec3 radiance;
} f;

uniform sampler2D frontDepth;
uniform sampler2D backDepth;
uniform sampler2D hostDepth;
uniform mat4 inverseProjection;
uniform vec2 viewportSize;
uniform float discardBelow;  // diagnostics only (render benchmark): 0 in normal use

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

// Distance from the eye to the surface a depth-buffer value describes, along the pixel ray.
float eyeDistance(float depth, vec2 ndc) {
    vec4 p = inverseProjection * vec4(ndc, 2.0 * depth - 1.0, 1.0);
    return length(p.xyz / p.w);
}

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    float front = texelFetch(frontDepth, pixel, 0).r;
    if (front >= 1.0) discard;  // the ray misses the object
    float back = texelFetch(backDepth, pixel, 0).r;
    float host = texelFetch(hostDepth, pixel, 0).r;
    vec2 ndc = gl_FragCoord.xy / viewportSize * 2.0 - 1.0;
    vec4 far = inverseProjection * vec4(ndc, 1.0, 1.0);
    vec3 dir = normalize(far.xyz / far.w);
    float t0 = eyeDistance(front, ndc);
    float t1 = eyeDistance(back, ndc);
    if (host < 1.0) t1 = min(t1, eyeDistance(host, ndc));
    if (t1 <= t0) discard;

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
