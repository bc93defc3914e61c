#pragma once
// An OpenGL 4.5 core context with no window: OSMesa or EGL (surfaceless, on Mesa's
// llvmpipe here). Creating one makes it current and loads Lucent's GL functions
// (runtime/opengl.h); the caller renders into its own framebuffer objects.
#include <memory>
#include <string>

#include "runtime/opengl.h"

namespace lucent {

enum class GlBackend { Auto, OSMesa, Egl };

GlBackend parseGlBackend(const std::string& name);  // "osmesa", "egl" or "" (auto)

class OffscreenContext {
public:
    virtual ~OffscreenContext() = default;
    virtual const char* backendName() const = 0;
    // A context is current in one thread at a time: release() in the thread that
    // has it, then makeCurrent() in the one that takes it over (Throws Error).
    virtual void release() = 0;
    virtual void makeCurrent() = 0;
    // Throws Error("no usable OpenGL context: <backend>: <why>"). Auto tries EGL, then OSMesa.
    static std::unique_ptr<OffscreenContext> create(GlBackend backend);
};

std::unique_ptr<OffscreenContext> createOsmesaContext();
std::unique_ptr<OffscreenContext> createEglContext();

}  // namespace lucent
