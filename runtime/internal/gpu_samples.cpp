#include "runtime/internal/gpu_samples.h"

#include <algorithm>

#include "core/error.h"
#include "runtime/internal/gpu_layout.h"

namespace lucent {

void checkGpuCapacity(size_t samples, size_t coefficientsPerSample, uint64_t maxTexels, uint64_t maxBlockBytes) {
    const uint64_t texels = uint64_t(samples) * coefficientsPerSample;
    if (texels > maxTexels)
        throw Error("the sample set's " + std::to_string(samples) + " samples hold " + std::to_string(texels) +
                    " SH coefficients, more than the " + std::to_string(maxTexels) +
                    " texels of this OpenGL's largest texture buffer: preprocess with fewer samples or a lower "
                    "--sh-order");
    const uint64_t bytes = uint64_t(samples) * std::max(sizeof(gpu::Sample), sizeof(gpu::Received));
    if (bytes > maxBlockBytes)
        throw Error("the sample set's " + std::to_string(samples) + " samples need " + std::to_string(bytes) +
                    " bytes of shader storage, more than the " + std::to_string(maxBlockBytes) +
                    " this OpenGL allows: preprocess with fewer samples");
}

GpuSamples::GpuSamples(const SampleSet& samples)
    : source_(&samples),
      count_(samples.size()),
      shOrder_(int(samples.shOrder)),
      channels_(int(samples.channels)),
      parameters_(samples.parameters),
      homogeneous_(isHomogeneous(samples)),
      fromFront_(lucent::attenuatesFromFront(samples)),
      slabs_(findSlabs(samples)) {
    if (samples.shOrder > kMaxSampleShOrder)
        throw Error("sample set has SH order " + std::to_string(samples.shOrder) + "; the runtime evaluates at most " +
                    std::to_string(kMaxSampleShOrder));
    GLint maxTexels = 0;
    GLint64 maxBlockBytes = 0;
    glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &maxTexels);
    glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &maxBlockBytes);
    checkGpuCapacity(count_, samples.coefficientsPerSample(), uint64_t(maxTexels), uint64_t(maxBlockBytes));
    maxBlockBytes_ = uint64_t(maxBlockBytes);
    const std::vector<gpu::Sample> packed = packSamples(samples);
    glCreateVertexArrays(1, &vao_);
    glCreateBuffers(3, buffers_);
    glNamedBufferStorage(buffers_[0], GLsizeiptr(std::max<size_t>(packed.size(), 1) * sizeof(gpu::Sample)),
                         packed.empty() ? nullptr : packed.data(), 0);
    glNamedBufferStorage(buffers_[2], GLsizeiptr(std::max<size_t>(count_, 1) * sizeof(gpu::Received)), nullptr, 0);
}

void GpuSamples::uploadCoefficients() {
    const std::vector<float>& sh = source_->coefficients();
    glNamedBufferStorage(buffers_[1], GLsizeiptr(std::max<size_t>(sh.size(), 1) * sizeof(float)),
                         sh.empty() ? nullptr : sh.data(), 0);
    // The coefficients are read through a texture buffer: llvmpipe gathers texel
    // fetches with vector instructions where it loads storage buffers lane by lane
    // (the received light's pass took half the time), and its largest
    // texture buffer holds 4x what one storage block may (512 against 128 MB).
    glCreateTextures(GL_TEXTURE_BUFFER, 1, &coefficientTexture_);
    glTextureBuffer(coefficientTexture_, GL_R32F, buffers_[1]);
}

GpuSamples::~GpuSamples() {
    if (coefficientTexture_) glDeleteTextures(1, &coefficientTexture_);
    glDeleteBuffers(3, buffers_);
    if (tracedBuffer_) glDeleteBuffers(1, &tracedBuffer_);
    if (environmentBuffer_) glDeleteBuffers(1, &environmentBuffer_);
    glDeleteVertexArrays(1, &vao_);
}

void GpuSamples::bind(bool coefficients) {
    if (coefficients && !coefficientTexture_) uploadCoefficients();
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::kBindingSamples, buffers_[0]);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::kBindingReceived, buffers_[2]);
    glBindTextureUnit(gpu::kUnitCoefficients, coefficients ? coefficientTexture_ : 0);
    if (tracedBuffer_) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::kBindingTracedDepths, tracedBuffer_);
    if (environmentBuffer_) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::kBindingEnvironmentSh, environmentBuffer_);
}

// bands^2 coefficients and one gradient per sample (sample_light.glsl, environmentRecords).
static uint64_t environmentRecords(int bands) { return uint64_t(bands) * uint64_t(bands) + 1u; }

bool GpuSamples::environmentFits(int bands) const {
    return uint64_t(count_) * environmentRecords(bands) * 16u <= maxBlockBytes_;
}

void GpuSamples::computeEnvironment(int bands) {
    if (bands != environmentBands_) {
        if (environmentBuffer_) glDeleteBuffers(1, &environmentBuffer_);
        glCreateBuffers(1, &environmentBuffer_);
        glNamedBufferStorage(environmentBuffer_,
                             GLsizeiptr(std::max<size_t>(count_, 1) * environmentRecords(bands) * sizeof(glm::vec4)),
                             nullptr, 0);
        environmentBands_ = bands;
    }
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::kBindingEnvironmentSh, environmentBuffer_);
    if (count_ > 0) glDispatchCompute(GLuint((count_ + 63) / 64), 1, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

void GpuSamples::setTracedDepths(const std::vector<glm::vec4>& depths) {
    if (!tracedBuffer_) glCreateBuffers(1, &tracedBuffer_);
    glNamedBufferData(tracedBuffer_, GLsizeiptr(std::max<size_t>(depths.size(), 1) * sizeof(glm::vec4)),
                      depths.empty() ? nullptr : depths.data(), GL_STATIC_DRAW);
    tracedValid = true;
}

void GpuSamples::draw() const {
    if (count_ == 0) return;
    glBindVertexArray(vao_);
    // In batches, each flushed: llvmpipe rasterizes what it has binned only at a
    // flush, so one draw of every proxy kept its raster threads idle while the
    // application thread ran the proxies' vertex work. Flushed in batches, the
    // raster threads shade a batch while the next is transformed
    // (docs/runtime.md, Speed). Sixteen rather than four: llvmpipe's binned data
    // and vertex buffers are per batch and reused by the next, so less memory is
    // touched for the first time (32 gained nothing more). The blending adds, so the order
    // of the batches does not matter.
    constexpr size_t kBatches = 16, kSmallestBatch = 2048;
    const size_t batch = std::max((count_ + kBatches - 1) / kBatches, kSmallestBatch);
    for (size_t first = 0; first < count_; first += batch) {
        glDrawArrays(GL_POINTS, GLint(first), GLsizei(std::min(batch, count_ - first)));
        if (first + batch < count_) glFlush();
    }
}

void GpuSamples::computeReceived() const {
    if (count_ == 0) return;
    glDispatchCompute(GLuint((count_ + 63) / 64), 1, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

}  // namespace lucent
