#include "runtime/blocker_shadows.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "runtime/embedded_shaders.h"

namespace lucent {

namespace {

// The six faces around a point light, in the order the shader picks them:
// +x, -x, +y, -y, +z, -z (2 * axis + negative).
glm::mat4 cubeFaceView(const glm::vec3& eye, int face) {
    glm::vec3 axis(0.0f);
    axis[face / 2] = face % 2 ? -1.0f : 1.0f;
    const glm::vec3 up = face / 2 == 1 ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0);
    return glm::lookAt(eye, eye + axis, up);
}

}  // namespace

int BlockerShadows::resolutionFor(size_t lightCount) {
    if (lightCount <= 4) return 512;
    return std::max(64, int(512.0 * std::sqrt(4.0 / double(lightCount))));
}

BlockerShadows::BlockerShadows(const std::vector<const TriangleMesh*>& blockers)
    : program_{{GL_VERTEX_SHADER, "shaders/mesh.vert", shaders::mesh_vert},
               {GL_FRAGMENT_SHADER, "shaders/blocker_distance.frag", shaders::blocker_distance_frag}} {
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

void BlockerShadows::render(const std::vector<Light>& lights) {
    const int layers = std::max<int>(6 * int(lights.size()), 6);
    const int size = resolutionFor(lights.size());
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
    // Enclose the blockers: their bounding sphere sets the planes of every view.
    const glm::vec3 centre(bounds_.center());
    const float radius = std::max(float(0.5 * bounds_.diagonal()), 1e-6f);
    std::vector<glm::mat4> views(size_t(layers), glm::mat4(1.0f));
    for (size_t j = 0; j < lights.size(); ++j) {
        const Light& l = lights[j];
        if (l.type == Light::Type::Point) {
            const glm::vec3 eye(l.position);
            const float farPlane = glm::length(centre - eye) + radius;
            const glm::mat4 projection = glm::perspective(glm::radians(90.0f), 1.0f, farPlane * 1e-5f, farPlane * 1.01f);
            for (int face = 0; face < 6; ++face) views[6 * j + face] = projection * cubeFaceView(eye, face);
        } else {
            // Looking along the light from outside the sphere; the map stores dot(x, d).
            const glm::vec3 d = glm::normalize(glm::vec3(l.direction));
            const glm::vec3 up = std::abs(d.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
            const glm::mat4 view = glm::lookAt(centre - 2.0f * radius * d, centre, up);
            views[6 * j] = glm::ortho(-radius, radius, -radius, radius, 0.5f * radius, 3.5f * radius) * view;
        }
    }
    glNamedBufferSubData(views_, 0, GLsizeiptr(views.size() * sizeof(glm::mat4)), views.data());

    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer_);
    glViewport(0, 0, size, size);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glEnable(GL_BLEND);
    glBlendEquation(GL_MIN);
    glUseProgram(program_.id());
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
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 4, views_);
}

}  // namespace lucent
