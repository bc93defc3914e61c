#pragma once
// The OpenCL device the hybrid runs on, with clear errors for what can go wrong:
// no platform or device, a kernel that does not build (with its build log), a
// grid that does not fit. Private to hybrid/: nothing above it sees OpenCL.
#define CL_HPP_TARGET_OPENCL_VERSION 120
#define CL_HPP_MINIMUM_OPENCL_VERSION 120
#define CL_HPP_ENABLE_EXCEPTIONS
#include <CL/opencl.hpp>
#include <glm/glm.hpp>

#include <string>
#include <string_view>
#include <vector>

namespace lucent {
// The text of an embedded kernel file of hybrid/internal (generated), or nullptr.
const char* hybridKernel(std::string_view file);
}  // namespace lucent

namespace lucent::hybrid {

class ClDevice {
public:
    // The first GPU of any platform, else the first device (PoCL's CPU device here).
    // Throws Error when there is none.
    ClDevice();

    // Why no device can be had, or empty when one can.
    static std::string unavailableReason();

    // Builds the kernel files (embedded, or given as text by tests) after the
    // shared layout (cl_layout.h). Throws Error with the build log on failure.
    cl::Program build(const std::vector<std::string>& files) const;
    cl::Program buildSource(const std::string& source, const std::string& name) const;

    // Throws Error when `bytes` in all, or `largestBuffer` in one buffer, exceed
    // what the device can hold; what names the work ("a 128^3 grid"). On a
    // device that shares the host's memory (PoCL on the CPU), hostBytes (the
    // host's own copies: sources uploaded, results read back) count too, and
    // everything must fit in the memory the machine has available: PoCL
    // reports nearly all of it as the device's, and a 256^3 mdom grid that
    // passed that check was killed by the kernel at 24 GB.
    void checkMemory(size_t bytes, size_t largestBuffer, const std::string& what, size_t hostBytes = 0) const;

    // Whether the device's memory is the host's (PoCL on the CPU).
    bool sharesHostMemory() const;
    // What the machine can still allocate without swapping (MemAvailable), or fallback.
    static size_t hostMemoryAvailable(size_t fallback);

    std::string name() const;

    cl::Context context;
    cl::Device device;
    // Two in-order queues so that marching and diffusion can overlap (thesis fig. 4.1).
    cl::CommandQueue marchQueue, latticeQueue;
};

// A host vector as an OpenCL float4 (rgb or xyz, and w).
inline cl_float4 float4Of(const glm::dvec3& v, double w = 0.0) {
    return {{float(v.x), float(v.y), float(v.z), float(w)}};
}

// A read-write buffer of `bytes` zeros (at least 16: OpenCL refuses empty buffers).
cl::Buffer zeroBuffer(const cl::Context& context, size_t bytes);

// "CL_OUT_OF_RESOURCES (-5)" and the like.
std::string clErrorText(cl_int code);

}  // namespace lucent::hybrid
