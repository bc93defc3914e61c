#include "runtime/internal/sample_packing.h"

#include <map>
#include <utility>

namespace lucent {

std::vector<gpu::Sample> packSamples(const SampleSet& samples) {
    std::vector<gpu::Sample> packed(samples.size());
    for (size_t i = 0; i < samples.size(); ++i) {
        const BoundaryBall& ball = samples.boundary[i];
        packed[i].centreWidth = glm::vec4(samples.positions[i], samples.widths[i]);
        packed[i].scattering = glm::vec4(samples.weights[i] * samples.extinction[i], 0.0f);
        packed[i].extinction = glm::vec4(samples.extinction[i], 0.0f);
        packed[i].region = glm::vec4(samples.region[i], ball.curvature, ball.share);
        packed[i].image = glm::vec4(samples.image[i], 0.0f);
        packed[i].ball = glm::vec4(ball.normal, ball.depth);
    }
    return packed;
}

bool isHomogeneous(const SampleSet& samples) {
    for (size_t i = 0; i < samples.size(); ++i)
        if (samples.extinction[i] != samples.extinction[0]) return false;
    return true;
}

SlabTable findSlabs(const SampleSet& samples) {
    SlabTable table;
    if (samples.parameters.regionAxis >= kNoRegionAxis || isHomogeneous(samples)) return table;
    std::map<std::pair<float, float>, glm::vec3> slabs;
    for (size_t i = 0; i < samples.size(); ++i) {
        const auto [it, inserted] =
            slabs.emplace(std::make_pair(samples.region[i].x, samples.region[i].y), samples.extinction[i]);
        if (!inserted && it->second != samples.extinction[i]) return table;
        if (slabs.size() > SlabTable::kMaxSlabs) return table;
    }
    for (const auto& [bounds, extinction] : slabs) {
        table.bounds.emplace_back(bounds.first, bounds.second, 0.0f, 0.0f);
        table.extinction.emplace_back(extinction, 0.0f);
    }
    return table;
}

bool attenuatesFromFront(const SampleSet& samples) {
    return samples.parameters.scheme == SampleScheme::Lucent && (isHomogeneous(samples) || !findSlabs(samples).empty());
}

}  // namespace lucent
