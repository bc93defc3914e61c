#include "runtime/internal/blocker_shadows.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "runtime/internal/blocker_shadow_views.h"
#include "runtime/internal/gpu_layout.h"
#include "runtime/internal/placement_uniforms.h"

namespace lucent {

BlockerShadows::BlockerShadows(const std::vector<const TriangleMesh*>& blockers)
    : program_{{GL_VERTEX_SHADER, "mesh.vert"}, {GL_FRAGMENT_SHADER, "blocker_distance.frag"}} {
    for (const TriangleMesh* b : blockers) {
        meshes_.push_back(std::make_unique<GpuMesh>(*b));
        const Bounds3 bb = b->bounds();
        bounds_.extend(bb.min);
        bounds_.extend(bb.max);
    }
}

BlockerShadows::~BlockerShadows() { release(); }

void BlockerShadows::release() {
    if (framebuffer_) glDeleteFramebuffers(1, &framebuffer_);
    if (texture_) glDeleteTextures(1, &texture_);
    if (views_) glDeleteBuffers(1, &views_);
    framebuffer_ = texture_ = views_ = 0;
    layers_ = size_ = 0;
}

void BlockerShadows::render(const std::vector<Light>& lights, const Similarity& placement) {
    const int layers = blockerShadowLayers(lights.size());
    const int size = blockerShadowResolution(lights.size());
    if (layers != layers_ || size != size_) {
        release();
        layers_ = layers;
        size_ = size;
        glCreateTextures(GL_TEXTURE_2D_ARRAY, 1, &texture_);
        glTextureStorage3D(texture_, 1, GL_R32F, size, size, layers);
        glTextureParameteri(texture_, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTextureParameteri(texture_, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        glCreateFramebuffers(1, &framebuffer_);
        glCreateBuffers(1, &views_);
        glNamedBufferStorage(views_, GLsizeiptr(layers * sizeof(glm::mat4)), nullptr, GL_DYNAMIC_STORAGE_BIT);
    }
    const std::vector<glm::mat4> views = blockerShadowViews(lights, placedBox(bounds_, placement));
    glNamedBufferSubData(views_, 0, GLsizeiptr(views.size() * sizeof(glm::mat4)), views.data());

    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer_);
    glViewport(0, 0, size, size);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glEnable(GL_BLEND);
    glBlendEquation(GL_MIN);
    glUseProgram(program_.id());
    setMeshPlacement(program_, placement);
    const float far = 3.0e38f;
    for (int layer = 0; layer < layers; ++layer) {
        glNamedFramebufferTextureLayer(framebuffer_, GL_COLOR_ATTACHMENT0, texture_, 0, layer);
        glClearNamedFramebufferfv(framebuffer_, GL_COLOR, 0, &far);
        const Light* l = layerLight(lights, layer);
        if (!l) continue;
        if (layer % 6 == 0 && glCheckNamedFramebufferStatus(framebuffer_, GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
            throw Error("OpenGL: the blocker shadow framebuffer is incomplete");
        glUniform4fv(program_.uniform("light"), 1, glm::value_ptr(packedLight(*l)));
        glUniformMatrix4fv(program_.uniform("viewProjection"), 1, GL_FALSE, glm::value_ptr(views[size_t(layer)]));
        for (const auto& mesh : meshes_) mesh->draw();
    }
    glBlendEquation(GL_FUNC_ADD);
    glDisable(GL_BLEND);
}

void BlockerShadows::bind(GLuint textureUnit) const {
    glBindTextureUnit(textureUnit, texture_);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::kBindingShadowViews, views_);
}

}  // namespace lucent
