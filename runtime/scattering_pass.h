#pragma once
// A sample set on the GPU: centres, widths, weighted scattering and extinction
// coefficients, density-slab regions and SH coefficients in shader storage
// buffers, one point per sample.
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
    bool homogeneous() const { return homogeneous_; }

private:
    GLuint vao_ = 0, buffers_[3] = {0, 0, 0};
    size_t count_ = 0;
    int shOrder_ = 0, channels_ = 1;
    SampleParameters parameters_;
    bool homogeneous_ = true;
};

}  // namespace lucent
