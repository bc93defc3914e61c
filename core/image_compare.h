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

}  // namespace lucent
