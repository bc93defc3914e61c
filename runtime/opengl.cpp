#include "runtime/opengl.h"

#include <string>

#include "core/error.h"
#include "runtime/internal/gl.h"

namespace lucent {
namespace {
void* (*currentProc)(const char*) = nullptr;
LUCENT_GLADapiproc loadProc(const char* name) { return reinterpret_cast<LUCENT_GLADapiproc>(currentProc(name)); }
bool loaded = false;
}  // namespace

void loadGl(const char* backend, void* (*getProcAddress)(const char*)) {
    currentProc = getProcAddress;
    const int version = lucent_gladLoadGL(loadProc);
    if (version == 0) throw Error(std::string("no usable OpenGL context: ") + backend + ": cannot load OpenGL functions");
    if (LUCENT_GLAD_VERSION_MAJOR(version) * 10 + LUCENT_GLAD_VERSION_MINOR(version) < 45)
        throw Error(std::string("no usable OpenGL context: ") + backend + ": OpenGL " +
                    std::to_string(LUCENT_GLAD_VERSION_MAJOR(version)) + "." +
                    std::to_string(LUCENT_GLAD_VERSION_MINOR(version)) + " found, 4.5 core needed");
    loaded = true;
}

bool glLoaded() { return loaded; }

}  // namespace lucent
