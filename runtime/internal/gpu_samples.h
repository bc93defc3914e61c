#pragma once
// A sample set on the GPU: the Sample records of gpu_layout.h in a shader
// storage buffer, its SH coefficients in a texture buffer, room for the light
// each sample receives, and the slab table of its density; one point per sample.
#include <vector>

#include <glm/glm.hpp>

#include "core/sample_set.h"
#include "runtime/internal/gl.h"
#include "runtime/internal/sample_packing.h"

namespace lucent {

// Throws a lucent::Error when a set of this many samples does not fit this
// OpenGL's limits (GL_MAX_TEXTURE_BUFFER_SIZE texels for the SH coefficients,
// GL_MAX_SHADER_STORAGE_BLOCK_SIZE bytes for the per-sample records): past
// them what a shader reads is undefined.
void checkGpuCapacity(size_t samples, size_t coefficientsPerSample, uint64_t maxTexels, uint64_t maxBlockBytes);

class GpuSamples {
public:
    explicit GpuSamples(const SampleSet& samples);
    ~GpuSamples();
    GpuSamples(const GpuSamples&) = delete;
    GpuSamples& operator=(const GpuSamples&) = delete;

    // Binds the sample and received-light buffers and, when the program reads
    // them, the SH coefficients (gpu_layout.h). These are uploaded on the first
    // bind that asks for them, from the sample set given to the constructor,
    // which must outlive this: with the traced light in a medium of constant
    // density no program reads them, and they are most of the samples' bytes.
    void bind(bool coefficients);
    // One point per sample (buffers bound).
    void draw() const;
    // Runs the bound compute program over the samples, filling the received light.
    void computeReceived() const;
    // Whether the received-light buffer holds the light of the current lights and scale.
    bool receivedValid = false;
    float receivedScale = 0.0f;
    bool receivedTraced = false;  // whether it was computed from the traced depths
    // The environment's light projected onto SH per sample (environment_sh.comp),
    // bound at kBindingEnvironmentSh once computed; the bound compute program fills it.
    void computeEnvironment(int bands);
    bool environmentValid = false;
    float environmentScale = 0.0f;  // the medium scale it was projected at
    int environmentBands() const { return environmentBands_; }
    // Whether its records at this many bands fit one shader storage block (as tracedDepthsFit).
    bool environmentFits(int bands) const;
    // The traced optical depths of runtime/internal/traced_light.h, bound at
    // kBindingTracedDepths; tracedValid while they hold the current lights and placements.
    void setTracedDepths(const std::vector<glm::vec4>& depths);
    bool tracedValid = false;
    // Whether the depths for this many lights fit one shader storage block (past
    // GL_MAX_SHADER_STORAGE_BLOCK_SIZE a shader reads undefined values), at
    // records vec4s per sample and light (2 for the light through a refracting boundary).
    bool tracedDepthsFit(int lights, int records = 1) const {
        return uint64_t(count_) * uint64_t(lights) * uint64_t(records) * 16u <= maxBlockBytes_;
    }
    int shOrder() const { return shOrder_; }
    int channels() const { return channels_; }
    size_t size() const { return count_; }
    const SampleParameters& parameters() const { return parameters_; }
    bool homogeneous() const { return homogeneous_; }
    bool attenuatesFromFront() const { return fromFront_; }  // sample_packing.h
    const SlabTable& slabs() const { return slabs_; }

private:
    void uploadCoefficients();
    const SampleSet* source_;
    GLuint vao_ = 0, buffers_[3] = {0, 0, 0}, coefficientTexture_ = 0, tracedBuffer_ = 0, environmentBuffer_ = 0;
    size_t count_ = 0;
    uint64_t maxBlockBytes_ = 0;
    int shOrder_ = 0, channels_ = 1;
    SampleParameters parameters_;
    bool homogeneous_ = true;
    bool fromFront_ = false;
    SlabTable slabs_;
    int environmentBands_ = 0;
};

}  // namespace lucent
