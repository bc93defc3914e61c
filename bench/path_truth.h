#pragma once
// The ground truth the accuracy benchmarks measure against: --method path
// rendered twice with independent seeds, so that its own noise is measured and
// taken out of every error (luminanceRelativeRmse of three images).
#include <algorithm>

#include "core/image.h"
#include "core/loaded_scene.h"
#include "core/stopwatch.h"
#include "methods/method_table.h"

namespace lucent {

struct PathTruth {
    Image a, b, mean;      // the two renders and their mean
    double seconds = 0.0;  // the time of one of them
};

inline PathTruth pathTruth(const LoadedScene& scene, MethodSettings settings, int spp) {
    const MethodEntry& path = findMethod("path");
    const MethodOptions options = MethodOptions(path.options).set("samples", spp);
    PathTruth t;
    const Stopwatch stopwatch;
    settings.seed = 1;
    t.a = renderWith(path, *path.create(options), scene, settings);
    t.seconds = stopwatch.seconds();
    settings.seed = 2;
    t.b = renderWith(path, *path.create(options), scene, settings);
    t.mean = t.a;
    for (size_t i = 0; i < t.mean.pixels.size(); ++i) t.mean.pixels[i] = 0.5f * (t.a.pixels[i] + t.b.pixels[i]);
    return t;
}

// The mean luminance of an image (Rec. 709 weights).
inline double meanLuminance(const Image& image) {
    double sum = 0.0;
    for (const glm::vec3& c : image.pixels) sum += 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b;
    return sum / double(std::max<size_t>(1, image.pixels.size()));
}

}  // namespace lucent
