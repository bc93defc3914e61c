#include "runtime/internal/gpu_samples.h"

#include <algorithm>

#include "core/error.h"
#include "runtime/internal/gpu_layout.h"

namespace lucent {

GpuSamples::GpuSamples(const SampleSet& samples)
    : count_(samples.size()), shOrder_(int(samples.shOrder)), channels_(int(samples.channels)),
      parameters_(samples.parameters), homogeneous_(isHomogeneous(samples)), slabs_(findSlabs(samples)) {
    if (samples.shOrder > kMaxSampleShOrder)
        throw Error("sample set has SH order " + std::to_string(samples.shOrder) + "; the runtime evaluates at most " +
                    std::to_string(kMaxSampleShOrder));
    const std::vector<gpu::Sample> packed = packSamples(samples);
    glCreateVertexArrays(1, &vao_);
    glCreateBuffers(3, buffers_);
    glNamedBufferStorage(buffers_[0], GLsizeiptr(std::max<size_t>(packed.size(), 1) * sizeof(gpu::Sample)),
                         packed.empty() ? nullptr : packed.data(), 0);
    glNamedBufferStorage(buffers_[1], GLsizeiptr(std::max<size_t>(samples.sh.size(), 1) * sizeof(float)),
                         samples.sh.empty() ? nullptr : samples.sh.data(), 0);
    glNamedBufferStorage(buffers_[2], GLsizeiptr(std::max<size_t>(count_, 1) * sizeof(gpu::Received)), nullptr, 0);
}

GpuSamples::~GpuSamples() {
    glDeleteBuffers(3, buffers_);
    glDeleteVertexArrays(1, &vao_);
}

void GpuSamples::bind() const {
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::kBindingSamples, buffers_[0]);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::kBindingCoefficients, buffers_[1]);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::kBindingReceived, buffers_[2]);
}

void GpuSamples::draw() const {
    if (count_ == 0) return;
    glBindVertexArray(vao_);
    glDrawArrays(GL_POINTS, 0, GLsizei(count_));
}

void GpuSamples::computeReceived() const {
    if (count_ == 0) return;
    glDispatchCompute(GLuint((count_ + 63) / 64), 1, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

}  // namespace lucent
