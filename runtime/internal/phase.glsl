// What every program that lights or scatters shares: pi, and the
// Henyey-Greenstein phase function (thesis eq. 2.6) of the medium's mean cosine
// g, normalised over the sphere. The denominator is kept from zero so that
// g -> 1 (a forward peak) stays finite in single precision.
const float PI = 3.14159265358979;

float henyeyGreenstein(float g, float cosTheta) {
    float denom = max(1.0 + g * g - 2.0 * g * cosTheta, 1e-6);
    return (1.0 - g * g) / (4.0 * PI * denom * sqrt(denom));
}
