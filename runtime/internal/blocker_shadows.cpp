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
    Bounds3 world;  // the placed box's corners bound the placed blockers
    for (int corner = 0; corner < 8; ++corner)
        world.extend(
            placement.point(Vec3(corner & 1 ? bounds_.max.x : bounds_.min.x, corner & 2 ? bounds_.max.y : bounds_.min.y,
                                 corner & 4 ? bounds_.max.z : bounds_.min.z)));
    const std::vector<glm::mat4> views = blockerShadowViews(lights, world);
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
        const size_t j = size_t(layer / 6);
        if (j >= lights.size()) continue;
        const Light& l = lights[j];
        if (l.type == Light::Type::Directional && layer % 6 != 0) continue;
        if (layer == int(6 * j) &&
            glCheckNamedFramebufferStatus(framebuffer_, GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
            throw Error("OpenGL: the blocker shadow framebuffer is incomplete");
        const glm::vec4 packed = l.type == Light::Type::Point ? glm::vec4(glm::vec3(l.position), 1.0f)
                                                              : glm::vec4(glm::normalize(glm::vec3(l.direction)), 0.0f);
        glUniform4fv(program_.uniform("light"), 1, glm::value_ptr(packed));
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
