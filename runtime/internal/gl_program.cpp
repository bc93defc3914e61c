#include "runtime/internal/gl_program.h"

#include <algorithm>
#include <vector>

#include "core/error.h"
#include "runtime/internal/shader_source.h"

namespace lucent {
namespace {

std::string oneLine(std::string log) {
    std::replace(log.begin(), log.end(), '\n', ' ');
    while (!log.empty() && (log.back() == ' ' || log.back() == '\0')) log.pop_back();
    return log;
}

}  // namespace

GlProgram::GlProgram(const std::vector<Stage>& stages, const std::vector<std::string>& defines) {
    // Assemble every stage first, so that a missing file leaks no GL object.
    std::vector<std::string> sources;
    for (const Stage& stage : stages) {
        const char* text = stage.source ? stage.source : runtimeShader(stage.file);
        if (!text) throw Error(stage.file, "no such shader is embedded in the runtime");
        sources.push_back(assembleShaderSource(stage.file, text, defines, runtimeShader));
    }
    std::vector<GLuint> shaders;
    auto cleanUp = [&] {
        for (GLuint s : shaders) glDeleteShader(s);
    };
    size_t index = 0;
    for (const Stage& stage : stages) {
        const char* sourceText = sources[index++].c_str();
        const GLuint shader = glCreateShader(stage.type);
        shaders.push_back(shader);
        glShaderSource(shader, 1, &sourceText, nullptr);
        glCompileShader(shader);
        GLint ok = 0;
        glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
        if (!ok) {
            GLint length = 0;
            glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
            std::string log(size_t(std::max(length, 1)), '\0');
            glGetShaderInfoLog(shader, length, nullptr, log.data());
            cleanUp();
            throw Error(stage.file, "GLSL compile error: " + oneLine(log));
        }
    }
    id_ = glCreateProgram();
    for (GLuint s : shaders) glAttachShader(id_, s);
    glLinkProgram(id_);
    cleanUp();
    GLint ok = 0;
    glGetProgramiv(id_, GL_LINK_STATUS, &ok);
    if (!ok) {
        GLint length = 0;
        glGetProgramiv(id_, GL_INFO_LOG_LENGTH, &length);
        std::string log(size_t(std::max(length, 1)), '\0');
        glGetProgramInfoLog(id_, length, nullptr, log.data());
        glDeleteProgram(id_);
        std::string names;
        for (const Stage& stage : stages) names += (names.empty() ? "" : " + ") + stage.file;
        throw Error(names, "GLSL link error: " + oneLine(log));
    }
}

GlProgram::~GlProgram() {
    if (id_) glDeleteProgram(id_);
}

const GlProgram& GlProgramVariants::get(const std::vector<std::string>& defines) const {
    std::unique_ptr<GlProgram>& program = programs_[defines];
    if (!program) {
        auto built = std::make_unique<GlProgram>(stages_, defines);
        if (setUp_) setUp_(*built);
        program = std::move(built);
    }
    return *program;
}

}  // namespace lucent
