#pragma once
// A sample set on the GPU: centres, widths, weighted scattering and extinction
// coefficients, density-slab regions and SH coefficients in shader storage
// buffers, one point per sample.
#include <vector>

#include "core/sample_set.h"
#include "runtime/gl.h"

namespace lucent {

class GpuSamples {
public:
    explicit GpuSamples(const SampleSet& samples);
    ~GpuSamples();
    GpuSamples(const GpuSamples&) = delete;
    GpuSamples& operator=(const GpuSamples&) = delete;

    // Binds the sample (0), coefficient (2) and received-light (3) buffers.
    void bind() const;
    // One point per sample (buffers bound).
    void draw() const;
    // Runs the bound compute program over the samples, filling the received light.
    void computeReceived() const;
    // Whether the received-light buffer holds the light of the current lights and scale.
    bool receivedValid = false;
    float receivedScale = 0.0f;
    int shOrder() const { return shOrder_; }
    int channels() const { return channels_; }
    size_t size() const { return count_; }
    const SampleParameters& parameters() const { return parameters_; }
    // sigma_t is one constant: the attenuation towards the camera is exp(-sigma_t distance).
    bool homogeneous() const { return homogeneous_; }
    // The density slabs along parameters().regionAxis, when sigma_t is constant in
    // each: per slab [lo, hi, 0, 0] and [sigma_t rgb, 0], at most kMaxSlabs (else empty).
    static constexpr size_t kMaxSlabs = 16;
    const std::vector<glm::vec4>& slabBounds() const { return slabBounds_; }
    const std::vector<glm::vec4>& slabExtinction() const { return slabExtinction_; }

private:
    void findSlabs(const SampleSet& samples);
    GLuint vao_ = 0, buffers_[3] = {0, 0, 0};
    size_t count_ = 0;
    int shOrder_ = 0, channels_ = 1;
    SampleParameters parameters_;
    bool homogeneous_ = true;
    std::vector<glm::vec4> slabBounds_, slabExtinction_;
};

}  // namespace lucent
