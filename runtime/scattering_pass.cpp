#include "runtime/scattering_pass.h"

#include <map>
#include <utility>
#include <vector>

#include "core/error.h"

namespace lucent {
namespace {
constexpr size_t kVec4PerSample = 6;  // struct Sample of shaders/sample_light.glsl
}  // namespace

GpuSamples::GpuSamples(const SampleSet& samples)
    : count_(samples.size()), shOrder_(int(samples.shOrder)), channels_(int(samples.channels)),
      parameters_(samples.parameters) {
    if (samples.shOrder > kMaxSampleShOrder)
        throw Error("sample set has SH order " + std::to_string(samples.shOrder) + "; the runtime evaluates at most " +
                    std::to_string(kMaxSampleShOrder));
    // struct Sample of shaders/sample_light.glsl
    std::vector<glm::vec4> packed(kVec4PerSample * count_);
    for (size_t i = 0; i < count_; ++i) {
        packed[kVec4PerSample * i + 0] = glm::vec4(samples.positions[i], samples.widths[i]);
        packed[kVec4PerSample * i + 1] = glm::vec4(samples.scattering[i], 0.0f);
        packed[kVec4PerSample * i + 2] = glm::vec4(samples.extinction[i], 0.0f);
        packed[kVec4PerSample * i + 3] = glm::vec4(samples.region[i], 0.0f, 0.0f);
        packed[kVec4PerSample * i + 4] = glm::vec4(samples.image[i], 0.0f);
        const BoundaryBall& ball = samples.boundary[i];
        packed[kVec4PerSample * i + 5] = glm::vec4(ball.normal, ball.depth);
        packed[kVec4PerSample * i + 3].z = ball.curvature;
        packed[kVec4PerSample * i + 3].w = ball.share;
        homogeneous_ = homogeneous_ && samples.extinction[i] == samples.extinction[0];
    }
    if (parameters_.regionAxis < kNoRegionAxis && !homogeneous_) findSlabs(samples);
    glCreateVertexArrays(1, &vao_);
    glCreateBuffers(3, buffers_);
    glNamedBufferStorage(buffers_[0], GLsizeiptr(std::max<size_t>(packed.size(), 1) * sizeof(glm::vec4)),
                         packed.empty() ? nullptr : packed.data(), 0);
    glNamedBufferStorage(buffers_[1], GLsizeiptr(std::max<size_t>(samples.sh.size(), 1) * sizeof(float)),
                         samples.sh.empty() ? nullptr : samples.sh.data(), 0);
    // struct Received of shaders/sample_light.glsl
    glNamedBufferStorage(buffers_[2], GLsizeiptr(std::max<size_t>(count_, 1) * 3 * sizeof(glm::vec4)), nullptr, 0);
}

void GpuSamples::findSlabs(const SampleSet& samples) {
    std::map<std::pair<float, float>, glm::vec3> slabs;
    for (size_t i = 0; i < count_; ++i) {
        const auto [it, inserted] = slabs.emplace(std::make_pair(samples.region[i].x, samples.region[i].y), samples.extinction[i]);
        // A density that varies inside a slab (not layers): no table.
        if (!inserted && it->second != samples.extinction[i]) return;
        if (slabs.size() > kMaxSlabs) return;
    }
    for (const auto& [bounds, extinction] : slabs) {
        slabBounds_.emplace_back(bounds.first, bounds.second, 0.0f, 0.0f);
        slabExtinction_.emplace_back(extinction, 0.0f);
    }
}

GpuSamples::~GpuSamples() {
    glDeleteBuffers(3, buffers_);
    glDeleteVertexArrays(1, &vao_);
}

void GpuSamples::bind() const {
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, buffers_[0]);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, buffers_[1]);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 3, buffers_[2]);
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
