#pragma once
// The path tracer's radiance at one spot, for the tests that compare it with a
// published or closed-form value: a 2x2 image through a 0.01-degree camera
// (placed by the caller), the mean of its four pixels (green channel) and the
// standard error of that mean.
#include <cmath>
#include <string>
#include <vector>

#include "reference/path_tracer.h"

namespace lucent::test {

struct SpotRadiance {
    double mean = 0.0, standardError = 0.0;
};

inline SpotRadiance spotRadiance(SceneDesc scene, const PathSettings& settings) {
    scene.camera.fovYDegrees = 0.01;
    scene.camera.width = scene.camera.height = 2;
    std::vector<std::string> warnings;
    const std::vector<VolumeObject> objects = loadObjects(scene, warnings);
    const PathTracer::Result r = PathTracer(scene, objects).render(settings);
    SpotRadiance spot;
    double variance = 0.0;
    for (size_t i = 0; i < 4; ++i) {
        spot.mean += r.mean.pixels[i].g / 4.0;
        variance += std::pow(r.standardError.pixels[i].g / 4.0, 2);
    }
    spot.standardError = std::sqrt(variance);
    return spot;
}

}  // namespace lucent::test
