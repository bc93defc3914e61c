#pragma once
// A linked GLSL program. Compile and link failures throw Error with the shader's
// name and the driver's log on one line.
#include <string>

#include "runtime/gl.h"

namespace lucent {

class GlProgram {
public:
    struct Stage {
        GLenum type;
        const char* name;    // shown in errors, e.g. "shaders/scatter.frag"
        const char* source;
    };
    GlProgram(std::initializer_list<Stage> stages);
    ~GlProgram();
    GlProgram(const GlProgram&) = delete;
    GlProgram& operator=(const GlProgram&) = delete;

    GLuint id() const { return id_; }
    GLint uniform(const char* name) const { return glGetUniformLocation(id_, name); }

private:
    GLuint id_ = 0;
};

}  // namespace lucent
