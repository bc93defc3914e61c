#include "runtime/offscreen_context.h"

#include "core/error.h"

namespace lucent {

GlBackend parseGlBackend(const std::string& name) {
    if (name.empty() || name == "auto") return GlBackend::Auto;
    if (name == "osmesa") return GlBackend::OSMesa;
    if (name == "egl") return GlBackend::Egl;
    throw Error("unknown OpenGL backend '" + name + "' (expected osmesa or egl)");
}

std::unique_ptr<OffscreenContext> OffscreenContext::create(GlBackend backend) {
    switch (backend) {
        case GlBackend::OSMesa:
            return createOsmesaContext();
        case GlBackend::Egl:
            return createEglContext();
        case GlBackend::Auto:
            break;
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

}  // namespace lucent
