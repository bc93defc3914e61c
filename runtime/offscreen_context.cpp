#include "runtime/offscreen_context.h"

#include "core/error.h"
#include "runtime/gl.h"

namespace lucent {

GlBackend parseGlBackend(const std::string& name) {
    if (name.empty() || name == "auto") return GlBackend::Auto;
    if (name == "osmesa") return GlBackend::OSMesa;
    if (name == "egl") return GlBackend::Egl;
    throw Error("unknown OpenGL backend '" + name + "' (expected osmesa or egl)");
}

std::unique_ptr<OffscreenContext> OffscreenContext::create(GlBackend backend) {
    switch (backend) {
        case GlBackend::OSMesa: return createOsmesaContext();
        case GlBackend::Egl: return createEglContext();
        case GlBackend::Auto: break;
    }
    try {
        return createEglContext();
    } catch (const Error& eglError) {
        try {
            return createOsmesaContext();
        } catch (const Error& osmesaError) {
            throw Error(std::string(eglError.what()) + "; " + osmesaError.what());
        }
    }
}

namespace {
void* (*currentProc)(const char*) = nullptr;
GLADapiproc loadProc(const char* name) { return reinterpret_cast<GLADapiproc>(currentProc(name)); }
}  // namespace

void loadGl(const char* backend, void* (*proc)(const char*)) {
    currentProc = proc;
    const int version = gladLoadGL(loadProc);
    if (version == 0) throw Error(std::string("no usable OpenGL context: ") + backend + ": cannot load OpenGL functions");
    if (GLAD_VERSION_MAJOR(version) * 10 + GLAD_VERSION_MINOR(version) < 45)
        throw Error(std::string("no usable OpenGL context: ") + backend + ": OpenGL " +
                    std::to_string(GLAD_VERSION_MAJOR(version)) + "." + std::to_string(GLAD_VERSION_MINOR(version)) +
                    " found, 4.5 core needed");
}

}  // namespace lucent
