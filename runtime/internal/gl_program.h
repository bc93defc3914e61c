#pragma once
// A linked GLSL program. Each stage is a shader file embedded from beside the
// class that owns it (runtime/internal/*, cmake/EmbedShaders.cmake), assembled
// with its #includes and defines (shader_source.h). Compile and link failures
// throw Error with the shader's name and the driver's log on one line.
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

#include "runtime/internal/gl.h"

namespace lucent {

// The runtime's embedded shader files by name (generated; nullptr if none).
const char* runtimeShader(std::string_view file);

class GlProgram {
public:
    struct Stage {
        GLenum type;
        std::string file;              // e.g. "scatter.frag"; shown in errors
        const char* source = nullptr;  // nullptr: runtimeShader(file)
    };
    explicit GlProgram(std::initializer_list<Stage> stages, const std::vector<std::string>& defines = {});
    ~GlProgram();
    GlProgram(const GlProgram&) = delete;
    GlProgram& operator=(const GlProgram&) = delete;

    GLuint id() const { return id_; }
    GLint uniform(const char* name) const { return glGetUniformLocation(id_, name); }

private:
    GLuint id_ = 0;
};

}  // namespace lucent
