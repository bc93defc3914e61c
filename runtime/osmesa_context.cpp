// OSMesa: Mesa's off-screen interface. Deprecated upstream but present in
// Debian 12's Mesa 22.3, where it gives a 4.5 core context on llvmpipe.
#include <GL/osmesa.h>
#include <dlfcn.h>

#include <string>
#include <vector>

#include "core/error.h"
#include "runtime/offscreen_context.h"

namespace lucent {
namespace {

// libOSMesa links LLVM, and a program linked to it loads and relocates LLVM
// before main, in every command, most of which never draw with OSMesa (it was
// most of `lucent --version`'s time; docs/architecture.md). So it
// is opened here, on first use. 8 is the ABI's major version since Mesa 10.
constexpr const char* kLibrary = "libOSMesa.so.8";

struct OsmesaApi {
    decltype(&OSMesaCreateContextAttribs) createContextAttribs;
    decltype(&OSMesaMakeCurrent) makeCurrent;
    decltype(&OSMesaGetProcAddress) getProcAddress;
    decltype(&OSMesaDestroyContext) destroyContext;
};

template <typename Function>
void bind(void* library, const char* name, Function& out) {
    out = reinterpret_cast<Function>(dlsym(library, name));
    if (!out) throw Error(std::string("no usable OpenGL context: osmesa: ") + kLibrary + " has no " + name);
}

// Opened once per process (a static's initialisation is thread-safe, and a
// failure throws each time it is asked for, since the static is then not set).
const OsmesaApi& osmesa() {
    static const OsmesaApi api = [] {
        // RTLD_LOCAL: Mesa's and LLVM's names stay out of every later symbol lookup.
        void* library = dlopen(kLibrary, RTLD_NOW | RTLD_LOCAL);
        if (!library) {
            const char* why = dlerror();
            throw Error(std::string("no usable OpenGL context: osmesa: cannot load ") + kLibrary + ": " +
                        (why ? why : "unknown error"));
        }
        OsmesaApi a{};
        bind(library, "OSMesaCreateContextAttribs", a.createContextAttribs);
        bind(library, "OSMesaMakeCurrent", a.makeCurrent);
        bind(library, "OSMesaGetProcAddress", a.getProcAddress);
        bind(library, "OSMesaDestroyContext", a.destroyContext);
        return a;
    }();
    return api;
}

class OsmesaContext final : public OffscreenContext {
public:
    OsmesaContext() : api_(osmesa()) {
        const int attributes[] = {OSMESA_FORMAT,
                                  OSMESA_RGBA,
                                  OSMESA_DEPTH_BITS,
                                  24,
                                  OSMESA_PROFILE,
                                  OSMESA_CORE_PROFILE,
                                  OSMESA_CONTEXT_MAJOR_VERSION,
                                  4,
                                  OSMESA_CONTEXT_MINOR_VERSION,
                                  5,
                                  0};
        context_ = api_.createContextAttribs(attributes, nullptr);
        if (!context_)
            throw Error("no usable OpenGL context: osmesa: OSMesaCreateContextAttribs failed (no 4.5 core profile?)");
        // Lucent draws into its own framebuffer objects; the default buffer is a token.
        if (!api_.makeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, 1, 1)) {
            api_.destroyContext(context_);
            throw Error("no usable OpenGL context: osmesa: OSMesaMakeCurrent failed");
        }
        // The loader's callback is a plain function pointer: it reads the table itself.
        loadGl("osmesa", [](const char* name) { return reinterpret_cast<void*>(osmesa().getProcAddress(name)); });
    }
    ~OsmesaContext() override { api_.destroyContext(context_); }
    const char* backendName() const override { return "osmesa"; }
    // A null context and buffer unbind the calling thread's (Mesa's osmesa.c).
    void release() override { api_.makeCurrent(nullptr, nullptr, 0, 0, 0); }
    void makeCurrent() override {
        if (!api_.makeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, 1, 1))
            throw Error("no usable OpenGL context: osmesa: OSMesaMakeCurrent failed");
    }

private:
    const OsmesaApi& api_;
    OSMesaContext context_ = nullptr;
    std::vector<unsigned char> buffer_ = std::vector<unsigned char>(4, 0);
};

}  // namespace

std::unique_ptr<OffscreenContext> createOsmesaContext() { return std::make_unique<OsmesaContext>(); }

}  // namespace lucent
