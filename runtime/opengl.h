#pragma once
// How a host hands Lucent its OpenGL context, with no GL header in sight: Lucent
// keeps its own OpenGL 4.5 function pointers (a glad loader whose names are all
// prefixed lucent_, runtime/CMakeLists.txt), so a host that loads GL itself
// (glad, libepoxy, GLEW, ...) links beside it with no clash of symbols or macros.
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

}  // namespace lucent
