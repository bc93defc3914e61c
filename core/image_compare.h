#pragma once
// The error metric of DESIGN.md between an image and its reference, over the
// pixels where the reference exceeds 1e-3 of its maximum (all three channels).
#include "core/image.h"

namespace lucent {

struct ImageError {
    double relativeRmse = 0.0;               // RMSE / mean of the reference
    double meanAbsoluteRelativeError = 0.0;  // mean of |test - ref| / ref
    double meanRatio = 0.0;                  // mean of test / mean of reference: the overall bias
    size_t pixels = 0;                       // pixels compared
};

// Throws Error if the sizes differ. With awayFromSilhouette, pixels that have a
// pixel outside the mask within `margin` pixels are left out too.
ImageError compareImages(const Image& test, const Image& reference, int silhouetteMargin = 0);

// The multiple-scattering metric (docs/accuracy.md): relative RMSE of luminance
// (Rec. 709 weights), sqrt(sum (Y - Y_ref)^2 / sum Y_ref^2) over the pixels the
// reference lights at all. Throws Error if the sizes differ.
double luminanceRelativeRmse(const Image& test, const Image& reference);

}  // namespace lucent
