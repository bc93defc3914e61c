#include "core/image_compare.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace lucent {

namespace {

void checkSameSize(const Image& test, const Image& reference) {
    if (test.width != reference.width || test.height != reference.height)
        throw Error("images differ in size: " + std::to_string(test.width) + "x" + std::to_string(test.height) +
                    " against " + std::to_string(reference.width) + "x" + std::to_string(reference.height));
}

double luminance(const glm::vec3& c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }

}  // namespace

std::vector<bool> interiorPixels(const Image& reference, int margin) {
    float peak = 0.0f;
    for (const auto& p : reference.pixels) peak = std::max({peak, p.r, p.g, p.b});
    const float threshold = 1e-3f * peak;
    auto inMask = [&](int x, int y) {
        if (x < 0 || y < 0 || x >= reference.width || y >= reference.height) return false;
        const auto& p = reference.at(x, y);
        return p.r > threshold && p.g > threshold && p.b > threshold;
    };
    std::vector<bool> interior(reference.pixels.size(), false);
    for (int y = 0; y < reference.height; ++y)
        for (int x = 0; x < reference.width; ++x) {
            bool in = inMask(x, y);
            for (int dy = -margin; dy <= margin && in; ++dy)
                for (int dx = -margin; dx <= margin && in; ++dx) in = inMask(x + dx, y + dy);
            interior[size_t(y) * reference.width + x] = in;
        }
    return interior;
}

ImageError compareImages(const Image& test, const Image& reference, int margin) {
    checkSameSize(test, reference);
    const std::vector<bool> interior = interiorPixels(reference, margin);
    double squared = 0.0, relative = 0.0, sumTest = 0.0, sumReference = 0.0;
    size_t n = 0;
    for (int y = 0; y < reference.height; ++y)
        for (int x = 0; x < reference.width; ++x) {
            if (!interior[size_t(y) * reference.width + x]) continue;
            for (int c = 0; c < 3; ++c) {
                const double t = test.at(x, y)[c], r = reference.at(x, y)[c];
                squared += (t - r) * (t - r);
                relative += std::abs(t - r) / r;
                sumTest += t;
                sumReference += r;
            }
            ++n;
        }
    ImageError e;
    e.pixels = n;
    if (n == 0) return e;
    const double mean = sumReference / (3.0 * n);
    e.relativeRmse = std::sqrt(squared / (3.0 * n)) / mean;
    e.meanAbsoluteRelativeError = relative / (3.0 * n);
    e.meanRatio = sumTest / sumReference;
    return e;
}

NoisyReferenceError luminanceRelativeRmse(const Image& test, const Image& a, const Image& b) {
    checkSameSize(test, a);
    checkSameSize(test, b);
    double err = 0.0, noise = 0.0, norm = 0.0;
    for (size_t i = 0; i < a.pixels.size(); ++i) {
        const double ya = luminance(a.pixels[i]), yb = luminance(b.pixels[i]), t = 0.5 * (ya + yb);
        if (!(t > 0.0)) continue;
        const double d = luminance(test.pixels[i]) - t;
        err += d * d;
        noise += 0.25 * (ya - yb) * (ya - yb);
        norm += t * t;
    }
    NoisyReferenceError e;
    if (!(norm > 0.0)) return e;
    e.raw = std::sqrt(err / norm);
    e.noise = std::sqrt(noise / norm);
    e.debiased = std::sqrt(std::max(0.0, err - noise) / norm);
    return e;
}

double luminanceRelativeRmse(const Image& test, const Image& reference) {
    checkSameSize(test, reference);
    double err = 0.0, norm = 0.0;
    for (size_t i = 0; i < reference.pixels.size(); ++i) {
        const double t = luminance(reference.pixels[i]);
        if (!(t > 0.0)) continue;
        const double d = luminance(test.pixels[i]) - t;
        err += d * d;
        norm += t * t;
    }
    return norm > 0.0 ? std::sqrt(err / norm) : 0.0;
}

}  // namespace lucent
