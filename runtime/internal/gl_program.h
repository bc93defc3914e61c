#pragma once
// A linked GLSL program. Each stage is a shader file embedded from beside the
// class that owns it (runtime/internal/*, cmake/EmbedShaders.cmake), assembled
// with its #includes and defines (shader_source.h). Compile and link failures
// throw Error with the shader's name and the driver's log on one line.
#include <functional>
#include <initializer_list>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
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
    explicit GlProgram(std::initializer_list<Stage> stages, const std::vector<std::string>& defines = {})
        : GlProgram(std::vector<Stage>(stages), defines) {}
    GlProgram(const std::vector<Stage>& stages, const std::vector<std::string>& defines);
    ~GlProgram();
    GlProgram(const GlProgram&) = delete;
    GlProgram& operator=(const GlProgram&) = delete;

    GLuint id() const { return id_; }
    GLint uniform(const char* name) const { return glGetUniformLocation(id_, name); }

private:
    GLuint id_ = 0;
};

// One program's compile-time variants, each linked the first time it is asked
// for. llvmpipe runs the body of every branch a program holds, taken or not
// (docs/runtime.md), so what an object may lack is a define left out of its
// variant, never a uniform the shader tests.
class GlProgramVariants {
public:
    // setUp runs once on each new variant (its constant uniforms, texture units).
    explicit GlProgramVariants(std::vector<GlProgram::Stage> stages, std::function<void(const GlProgram&)> setUp = {})
        : stages_(std::move(stages)), setUp_(std::move(setUp)) {}

    // The variant with exactly these defines, in this order.
    const GlProgram& get(const std::vector<std::string>& defines = {}) const;

private:
    std::vector<GlProgram::Stage> stages_;
    std::function<void(const GlProgram&)> setUp_;
    mutable std::map<std::vector<std::string>, std::unique_ptr<GlProgram>> programs_;
};

}  // namespace lucent
