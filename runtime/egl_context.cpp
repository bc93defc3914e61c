// EGL without a window system: Mesa's surfaceless platform (or the device
// platform), a 4.5 core context made current with no surface at all.
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstring>
#include <string>

#include "core/error.h"
#include "runtime/offscreen_context.h"

namespace lucent {
namespace {

[[noreturn]] void fail(const std::string& why) { throw Error("no usable OpenGL context: egl: " + why); }

bool hasExtension(const char* list, const char* name) {
    if (!list) return false;
    const size_t n = std::strlen(name);
    for (const char* p = std::strstr(list, name); p; p = std::strstr(p + 1, name))
        if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
    return false;
}

class EglContext final : public OffscreenContext {
public:
    EglContext() {
        const char* clientExtensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
        auto getPlatformDisplay =
            reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
        if (!getPlatformDisplay) fail("eglGetPlatformDisplayEXT is missing");
        if (hasExtension(clientExtensions, "EGL_MESA_platform_surfaceless"))
            display_ = getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        if (display_ == EGL_NO_DISPLAY && hasExtension(clientExtensions, "EGL_EXT_platform_device")) {
            auto queryDevices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
            EGLDeviceEXT device;
            EGLint count = 0;
            if (queryDevices && queryDevices(1, &device, &count) && count > 0)
                display_ = getPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, device, nullptr);
        }
        if (display_ == EGL_NO_DISPLAY) fail("no surfaceless or device platform display");
        EGLint major = 0, minor = 0;
        if (!eglInitialize(display_, &major, &minor)) fail("eglInitialize failed (is libgl1-mesa-dri installed?)");
        if (!eglBindAPI(EGL_OPENGL_API)) fail("eglBindAPI(EGL_OPENGL_API) failed");
        const EGLint configAttributes[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_SURFACE_TYPE, EGL_PBUFFER_BIT,
                                           EGL_NONE};
        EGLConfig config;
        EGLint configs = 0;
        if (!eglChooseConfig(display_, configAttributes, &config, 1, &configs) || configs == 0)
            fail("no OpenGL-renderable config");
        const EGLint contextAttributes[] = {
            EGL_CONTEXT_MAJOR_VERSION,           4,       EGL_CONTEXT_MINOR_VERSION, 5, EGL_CONTEXT_OPENGL_PROFILE_MASK,
            EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
        context_ = eglCreateContext(display_, config, EGL_NO_CONTEXT, contextAttributes);
        if (context_ == EGL_NO_CONTEXT) fail("eglCreateContext failed for OpenGL 4.5 core");
        if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_))
            fail("eglMakeCurrent without a surface failed (EGL_KHR_surfaceless_context missing?)");
        loadGl("egl", [](const char* name) { return reinterpret_cast<void*>(eglGetProcAddress(name)); });
    }
    ~EglContext() override {
        eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        if (context_ != EGL_NO_CONTEXT) eglDestroyContext(display_, context_);
        eglTerminate(display_);
    }
    const char* backendName() const override { return "egl"; }
    void release() override { eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT); }
    void makeCurrent() override {
        if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_)) fail("eglMakeCurrent failed");
    }

private:
    EGLDisplay display_ = EGL_NO_DISPLAY;
    EGLContext context_ = EGL_NO_CONTEXT;
};

}  // namespace

std::unique_ptr<OffscreenContext> createEglContext() { return std::make_unique<EglContext>(); }

}  // namespace lucent
