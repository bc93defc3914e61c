#pragma once
// The reference's quadrature: adaptive Simpson along a ray, in pieces where the
// medium is optically deep. Header-only templates: the integrand is a lambda.
#include <algorithm>
#include <cmath>

#include "core/math.h"

namespace lucent {

inline double magnitude(const Rgb& c) { return std::max({std::abs(c.r), std::abs(c.g), std::abs(c.b)}); }

// Adaptive Simpson on [a, b] given f at a, midpoint and b, to absolute tolerance tol.
template <class F>
Rgb adaptiveSimpson(const F& f, double a, double b, const Rgb& fa, const Rgb& fm, const Rgb& fb, const Rgb& whole,
                    double tol, int depth) {
    const double m = 0.5 * (a + b);
    const Rgb flm = f(0.5 * (a + m)), frm = f(0.5 * (m + b));
    const Rgb left = (m - a) / 6.0 * (fa + 4.0 * flm + fm);
    const Rgb right = (b - m) / 6.0 * (fm + 4.0 * frm + fb);
    const Rgb delta = left + right - whole;
    if (depth <= 0 || magnitude(delta) <= 15.0 * tol) return left + right + delta / 15.0;  // Richardson step
    return adaptiveSimpson(f, a, m, fa, flm, fm, left, 0.5 * tol, depth - 1) +
           adaptiveSimpson(f, m, b, fm, frm, fb, right, 0.5 * tol, depth - 1);
}

// Integrates f over [a, b]: a fixed composite pass sizes the answer, then each
// panel is refined until its share of the tolerance is met.
// Each of the 8 panels is halved at most maxDepth times: past that a jump in f
// (a shadow's edge) is left with an error of its height times the panel over 2^maxDepth.
template <class F>
Rgb integrate(const F& f, double a, double b, double relativeTolerance, double absoluteFloor = 1e-300,
              int maxDepth = 24) {
    constexpr int kPanels = 8;
    const double h = (b - a) / kPanels;
    Rgb values[2 * kPanels + 1];
    for (int i = 0; i <= 2 * kPanels; ++i) values[i] = f(a + 0.5 * h * i);
    Rgb coarse(0.0);
    for (int p = 0; p < kPanels; ++p) coarse += h / 6.0 * (values[2 * p] + 4.0 * values[2 * p + 1] + values[2 * p + 2]);
    const double tol = std::max(relativeTolerance * magnitude(coarse) / kPanels, absoluteFloor);
    Rgb total(0.0);
    for (int p = 0; p < kPanels; ++p) {
        const double x0 = a + h * p;
        const Rgb whole = h / 6.0 * (values[2 * p] + 4.0 * values[2 * p + 1] + values[2 * p + 2]);
        total +=
            adaptiveSimpson(f, x0, x0 + h, values[2 * p], values[2 * p + 1], values[2 * p + 2], whole, tol, maxDepth);
    }
    return total;
}

// Optical depth of a segment beyond which its integrand, falling like
// exp(-sigma_t (t - t0)) from the entry, is integrated in pieces.
constexpr double kOpticalDepthInOnePiece = 8.0;

// f over [a, b] when the medium can be optically deep there: fixed panels would
// step over the thin sliver where the light is scattered (and the integral would
// grow with sigma_t). So pieces from the entry, 1/sigma long and four times longer
// each, every one to the tolerance of what came before: about log4(sigma L) pieces.
template <class F>
Rgb integrateIntoDenseMedium(const F& f, double a, double b, double sigmaMax, double relativeTolerance,
                             int maxDepth = 24) {
    if (!(sigmaMax * (b - a) > kOpticalDepthInOnePiece)) return integrate(f, a, b, relativeTolerance, 1e-300, maxDepth);
    Rgb total(0.0);
    double start = a, length = 1.0 / sigmaMax;
    while (start < b) {
        const double end = std::min(b, start + length);
        total +=
            integrate(f, start, end, relativeTolerance, relativeTolerance * magnitude(total) / 64.0 + 1e-300, maxDepth);
        start = end;
        length *= 4.0;
    }
    return total;
}

}  // namespace lucent
