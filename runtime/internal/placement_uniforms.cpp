#include "runtime/internal/placement_uniforms.h"

#include <glm/gtc/type_ptr.hpp>

namespace lucent {

void setMeshPlacement(const GlProgram& program, const Similarity& placement) {
    const glm::mat4 model(placement.matrix());
    const glm::mat3 rotation(placement.rotation);
    glProgramUniformMatrix4fv(program.id(), program.uniform("model"), 1, GL_FALSE, glm::value_ptr(model));
    glProgramUniformMatrix3fv(program.id(), program.uniform("modelRotation"), 1, GL_FALSE, glm::value_ptr(rotation));
}

void setSamplePlacement(const GlProgram& program, const Similarity& placement, float preprocessedScale) {
    const glm::mat3 rotation(placement.rotation);
    const glm::vec3 translation(placement.translation);
    glProgramUniformMatrix3fv(program.id(), program.uniform("modelRotation"), 1, GL_FALSE, glm::value_ptr(rotation));
    glProgramUniform3fv(program.id(), program.uniform("modelTranslation"), 1, glm::value_ptr(translation));
    glProgramUniform1f(program.id(), program.uniform("modelScale"), float(placement.scale));
    glProgramUniform1f(program.id(), program.uniform("preprocessedScale"), preprocessedScale);
}

}  // namespace lucent
