#include "runtime/opengl.h"

#include <string>

#include "core/error.h"
#include "core/statistics.h"
#include "core/stopwatch.h"
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
    if (version == 0)
        throw Error(std::string("no usable OpenGL context: ") + backend + ": cannot load OpenGL functions");
    if (LUCENT_GLAD_VERSION_MAJOR(version) * 10 + LUCENT_GLAD_VERSION_MINOR(version) < 45)
        throw Error(std::string("no usable OpenGL context: ") + backend + ": OpenGL " +
                    std::to_string(LUCENT_GLAD_VERSION_MAJOR(version)) + "." +
                    std::to_string(LUCENT_GLAD_VERSION_MINOR(version)) + " found, 4.5 core needed");
    loaded = true;
}

bool glLoaded() { return loaded; }

std::string glRenderer() {
    const char* name = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    return name ? name : "";
}

bool glIsSoftware() {
    const std::string name = glRenderer();
    return name.find("llvmpipe") != std::string::npos || name.find("softpipe") != std::string::npos ||
           name.find("swrast") != std::string::npos;
}

double timeGlWork(const std::function<void()>& work) {
    glFinish();
    const Stopwatch stopwatch;
    work();
    glFinish();
    return stopwatch.seconds();
}

double medianFrameSeconds(int warmup, int frames, const std::function<void()>& prepare,
                          const std::function<void()>& draw) {
    std::vector<double> times;
    for (int f = 0; f < warmup + frames; ++f) {
        prepare();
        const double seconds = timeGlWork(draw);
        if (f >= warmup) times.push_back(seconds);
    }
    return median(times);
}

}  // namespace lucent
