#pragma once
// How a host hands Lucent its OpenGL context, with no GL header in sight: Lucent
// keeps its own OpenGL 4.5 function pointers (a glad loader whose names are all
// prefixed lucent_, runtime/CMakeLists.txt), so a host that loads GL itself
// (glad, libepoxy, GLEW, ...) links beside it with no clash of symbols or macros.
#include <functional>
#include <string>

namespace lucent {

// An OpenGL object name (a GLuint) in Lucent's public interface.
using GlName = unsigned int;

// With the host's context current, loads Lucent's OpenGL 4.5 core functions
// through getProcAddress (glfwGetProcAddress, eglGetProcAddress, ...): once,
// before the first ScatteringRenderer. Throws Error("no usable OpenGL context:
// <backend>: <why>") when the context cannot give them.
void loadGl(const char* backend, void* (*getProcAddress)(const char*));

// Whether loadGl has succeeded in this process.
bool glLoaded();

// The current context's renderer (GL_RENDERER), for reports: "llvmpipe (LLVM
// 15.0.6, 256 bits)" on Mesa's software rasteriser.
std::string glRenderer();

// Whether that renderer rasterises on the CPU (llvmpipe, softpipe, swrast).
bool glIsSoftware();

// The wall time of the OpenGL work that work() gives, in seconds, counted as a
// frame's time is: the queue drained before it starts and after it ends, since
// the driver runs the commands on threads of its own, later.
double timeGlWork(const std::function<void()>& work);

// The median of timeGlWork(draw) over `frames` runs after `warmup` untimed ones;
// before each run, prepare() (binding and clearing the target) runs untimed.
double medianFrameSeconds(int warmup, int frames, const std::function<void()>& prepare,
                          const std::function<void()>& draw);

}  // namespace lucent
