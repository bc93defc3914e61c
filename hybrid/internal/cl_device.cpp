#include "hybrid/internal/cl_device.h"

#include <unistd.h>

#include <algorithm>
#include <fstream>
#include <sstream>

#include "core/error.h"

namespace lucent::hybrid {

std::string clErrorText(cl_int code) {
    const char* name = nullptr;
    switch (code) {
        case CL_DEVICE_NOT_FOUND:
            name = "CL_DEVICE_NOT_FOUND";
            break;
        case CL_OUT_OF_RESOURCES:
            name = "CL_OUT_OF_RESOURCES";
            break;
        case CL_OUT_OF_HOST_MEMORY:
            name = "CL_OUT_OF_HOST_MEMORY";
            break;
        case CL_MEM_OBJECT_ALLOCATION_FAILURE:
            name = "CL_MEM_OBJECT_ALLOCATION_FAILURE";
            break;
        case CL_BUILD_PROGRAM_FAILURE:
            name = "CL_BUILD_PROGRAM_FAILURE";
            break;
        case CL_INVALID_WORK_GROUP_SIZE:
            name = "CL_INVALID_WORK_GROUP_SIZE";
            break;
        case CL_INVALID_BUFFER_SIZE:
            name = "CL_INVALID_BUFFER_SIZE";
            break;
        case -1001:
            name = "CL_PLATFORM_NOT_FOUND_KHR";
            break;
        default:
            break;
    }
    return (name ? std::string(name) + " " : std::string("OpenCL error ")) + "(" + std::to_string(code) + ")";
}

namespace {

// All devices of all platforms, GPUs first.
std::vector<cl::Device> allDevices() {
    std::vector<cl::Platform> platforms;
    try {
        cl::Platform::get(&platforms);
    } catch (const cl::Error& e) {
        if (e.err() == -1001 /* CL_PLATFORM_NOT_FOUND_KHR: the ICD loader found none */) return {};
        throw Error(std::string("OpenCL: listing platforms failed: ") + clErrorText(e.err()));
    }
    std::vector<cl::Device> gpus, others;
    for (const cl::Platform& p : platforms) {
        std::vector<cl::Device> devices;
        try {
            p.getDevices(CL_DEVICE_TYPE_ALL, &devices);
        } catch (const cl::Error&) {
            continue;  // a platform without devices
        }
        for (const cl::Device& d : devices)
            (d.getInfo<CL_DEVICE_TYPE>() & CL_DEVICE_TYPE_GPU ? gpus : others).push_back(d);
    }
    gpus.insert(gpus.end(), others.begin(), others.end());
    return gpus;
}

const char* kNoDevice =
    "no OpenCL device found (install an OpenCL driver, for example Debian's pocl-opencl-icd; clinfo lists what the "
    "loader sees)";

}  // namespace

std::string ClDevice::unavailableReason() {
    try {
        return allDevices().empty() ? kNoDevice : "";
    } catch (const Error& e) {
        return e.what();
    }
}

ClDevice::ClDevice() {
    const std::vector<cl::Device> devices = allDevices();
    if (devices.empty()) throw Error(kNoDevice);
    device = devices.front();
    const std::string extensions = device.getInfo<CL_DEVICE_EXTENSIONS>();
    if (extensions.find("cl_khr_int64_base_atomics") == std::string::npos)
        throw Error("OpenCL device '" + name() + "' lacks cl_khr_int64_base_atomics, which the photon deposits need");
    try {
        context = cl::Context(device);
        marchQueue = cl::CommandQueue(context, device);
        latticeQueue = cl::CommandQueue(context, device);
    } catch (const cl::Error& e) {
        throw Error("OpenCL device '" + name() + "': " + e.what() + " failed: " + clErrorText(e.err()));
    }
}

std::string ClDevice::name() const {
    std::string n = device.getInfo<CL_DEVICE_NAME>();
    while (!n.empty() && (n.back() == '\0' || n.back() == ' ')) n.pop_back();
    return n;
}

cl::Program ClDevice::buildSource(const std::string& source, const std::string& what) const {
    cl::Program program(context, std::string(hybridKernel("cl_layout.h")) + "\n" + source);
    try {
        program.build({device}, "-cl-std=CL1.2");
    } catch (const cl::Error& e) {
        std::string log;
        try {
            log = program.getBuildInfo<CL_PROGRAM_BUILD_LOG>(device);
        } catch (const cl::Error&) {
        }
        while (!log.empty() && (log.back() == '\n' || log.back() == '\0')) log.pop_back();
        throw Error("OpenCL kernels " + what + " did not build on '" + name() + "' (" + clErrorText(e.err()) + "):\n" +
                    log);
    }
    return program;
}

cl::Program ClDevice::build(const std::vector<std::string>& files) const {
    std::string source, what;
    for (const std::string& f : files) {
        const char* text = hybridKernel(f);
        if (!text) throw Error("internal: no embedded kernel file " + f);
        source += "#line 1\n" + std::string(text) + "\n";
        what += (what.empty() ? "" : ", ") + f;
    }
    return buildSource(source, what);
}

cl::Buffer zeroBuffer(const cl::Context& context, size_t bytes) {
    std::vector<char> zeros(std::max<size_t>(bytes, 16), 0);
    return cl::Buffer(context, CL_MEM_READ_WRITE | CL_MEM_COPY_HOST_PTR, zeros.size(), zeros.data());
}

// What the kernel says can still be allocated without swapping (MemAvailable:
// free memory plus caches it can drop), or fallback when it does not say.
size_t ClDevice::hostMemoryAvailable(size_t fallback) {
    std::ifstream meminfo("/proc/meminfo");
    std::string key;
    size_t kib = 0;
    std::string unit;
    while (meminfo >> key >> kib >> unit)
        if (key == "MemAvailable:") return kib * 1024;
    return fallback;
}

bool ClDevice::sharesHostMemory() const {
    return device.getInfo<CL_DEVICE_HOST_UNIFIED_MEMORY>() == CL_TRUE ||
           device.getInfo<CL_DEVICE_TYPE>() == CL_DEVICE_TYPE_CPU;
}

void ClDevice::checkMemory(size_t bytes, size_t largestBuffer, const std::string& what, size_t hostBytes) const {
    const size_t total = device.getInfo<CL_DEVICE_GLOBAL_MEM_SIZE>();
    const size_t single = device.getInfo<CL_DEVICE_MAX_MEM_ALLOC_SIZE>();
    auto mib = [](size_t b) { return std::to_string((b + (1 << 20) - 1) >> 20) + " MiB"; };
    if (bytes > total || largestBuffer > single)
        throw Error("OpenCL device '" + name() + "' cannot hold " + what + ": it needs " + mib(bytes) +
                    " (largest buffer " + mib(largestBuffer) + "), the device has " + mib(total) + " (" + mib(single) +
                    " per buffer); use a smaller grid (--grid)");
    if (!sharesHostMemory()) return;
    const size_t available = hostMemoryAvailable(total);
    if (bytes + hostBytes > std::min(total, available))
        throw Error("OpenCL device '" + name() + "' cannot hold " + what + ": it needs " + mib(bytes) +
                    " on the device and " + mib(hostBytes) + " more on the host, which share this machine's " +
                    mib(std::min(total, available)) + " available; use a smaller grid (--grid)");
}

}  // namespace lucent::hybrid
