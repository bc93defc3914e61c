#pragma once
// The error metric of DESIGN.md between an image and its reference, over the
// pixels where the reference exceeds 1e-3 of its maximum (all three channels).
#include <vector>

#include "core/image.h"

namespace lucent {

struct ImageError {
    double relativeRmse = 0.0;               // RMSE / mean of the reference
    double meanAbsoluteRelativeError = 0.0;  // mean of |test - ref| / ref
    double meanRatio = 0.0;                  // mean of test / mean of reference: the overall bias
    size_t pixels = 0;                       // pixels compared
};

// The pixels compareImages compares: where the reference exceeds 1e-3 of its
// maximum in all three channels, with every pixel within margin pixels so too.
std::vector<bool> interiorPixels(const Image& reference, int margin);

// Throws Error if the sizes differ. With awayFromSilhouette, pixels that have a
// pixel outside the mask within `margin` pixels are left out too.
ImageError compareImages(const Image& test, const Image& reference, int silhouetteMargin = 0);

// The multiple-scattering metric (docs/accuracy.md): relative RMSE of luminance
// (Rec. 709 weights), sqrt(sum (Y - Y_ref)^2 / sum Y_ref^2) over the pixels the
// reference lights at all. Throws Error if the sizes differ.
double luminanceRelativeRmse(const Image& test, const Image& reference);

// The same against a Monte Carlo reference rendered twice with independent
// seeds, a and b. The reference is their mean, whose own noise adds to the
// test's error in quadrature: with e the truth's error of a single render,
// E (Y - (Ya + Yb) / 2)^2 = (Y - Y_true)^2 + var(e) / 2, and E (Ya - Yb)^2 =
// 2 var(e). So the noise is estimated from the two renders' difference and
// taken out. At g = 0.8 a 1024-path render of the sphere is 17% noisy per
// pixel: against it, a method 6% from the truth measured 18% (docs/accuracy.md).
struct NoisyReferenceError {
    double raw = 0.0;       // luminanceRelativeRmse(test, (a + b) / 2)
    double noise = 0.0;     // the mean's relative RMS noise, sqrt(sum (Ya - Yb)^2 / 4 / sum Yref^2)
    double debiased = 0.0;  // sqrt(max(0, raw^2 - noise^2)): the error against the noise-free truth
};
NoisyReferenceError luminanceRelativeRmse(const Image& test, const Image& a, const Image& b);

}  // namespace lucent
