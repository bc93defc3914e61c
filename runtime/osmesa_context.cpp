// OSMesa: Mesa's off-screen interface. Deprecated upstream but present in
// Debian 12's Mesa 22.3, where it gives a 4.5 core context on llvmpipe.
#include <GL/osmesa.h>

#include <vector>

#include "core/error.h"
#include "runtime/offscreen_context.h"

namespace lucent {
namespace {

class OsmesaContext final : public OffscreenContext {
public:
    OsmesaContext() {
        const int attributes[] = {OSMESA_FORMAT,        OSMESA_RGBA, OSMESA_DEPTH_BITS,          24,
                                  OSMESA_PROFILE,       OSMESA_CORE_PROFILE, OSMESA_CONTEXT_MAJOR_VERSION, 4,
                                  OSMESA_CONTEXT_MINOR_VERSION, 5, 0};
        context_ = OSMesaCreateContextAttribs(attributes, nullptr);
        if (!context_) throw Error("no usable OpenGL context: osmesa: OSMesaCreateContextAttribs failed (no 4.5 core profile?)");
        // Lucent draws into its own framebuffer objects; the default buffer is a token.
        if (!OSMesaMakeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, 1, 1)) {
            OSMesaDestroyContext(context_);
            throw Error("no usable OpenGL context: osmesa: OSMesaMakeCurrent failed");
        }
        loadGl("osmesa", [](const char* name) { return reinterpret_cast<void*>(OSMesaGetProcAddress(name)); });
    }
    ~OsmesaContext() override { OSMesaDestroyContext(context_); }
    const char* backendName() const override { return "osmesa"; }
    // A null context and buffer unbind the calling thread's (Mesa's osmesa.c).
    void release() override { OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0); }
    void makeCurrent() override {
        if (!OSMesaMakeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, 1, 1))
            throw Error("no usable OpenGL context: osmesa: OSMesaMakeCurrent failed");
    }

private:
    OSMesaContext context_ = nullptr;
    std::vector<unsigned char> buffer_ = std::vector<unsigned char>(4, 0);
};

}  // namespace

std::unique_ptr<OffscreenContext> createOsmesaContext() { return std::make_unique<OsmesaContext>(); }

}  // namespace lucent
