#include "runtime/internal/surface_pass.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <array>

#include "core/error.h"
#include "runtime/internal/frame_targets.h"
#include "runtime/internal/placement_uniforms.h"

namespace lucent {

SurfacePass::SurfacePass() = default;

SurfacePass::~SurfacePass() { release(); }

void SurfacePass::release() {
    if (framebuffer_) glDeleteFramebuffers(1, &framebuffer_);
    if (normals_) glDeleteTextures(1, &normals_);
    if (depths_) glDeleteTextures(1, &depths_);
    framebuffer_ = normals_ = depths_ = 0;
    width_ = height_ = 0;
}

void SurfacePass::resize(int width, int height) {
    if (width == width_ && height == height_) return;
    release();
    auto texture = [&](GLenum format) {
        GLuint t = 0;
        glCreateTextures(GL_TEXTURE_2D, 1, &t);
        glTextureStorage2D(t, 1, format, width, height);
        glTextureParameteri(t, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTextureParameteri(t, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        return t;
    };
    normals_ = texture(GL_RGBA32F);
    depths_ = texture(GL_DEPTH_COMPONENT32F);
    glCreateFramebuffers(1, &framebuffer_);
    glNamedFramebufferTexture(framebuffer_, GL_COLOR_ATTACHMENT0, normals_, 0);
    glNamedFramebufferTexture(framebuffer_, GL_DEPTH_ATTACHMENT, depths_, 0);
    if (glCheckNamedFramebufferStatus(framebuffer_, GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw Error("OpenGL: the surface's framebuffer is incomplete");
    width_ = width;
    height_ = height;
}

void SurfacePass::keepNearestFaces(const FrameContext& frame, size_t first, size_t end) {
    resize(frame.view.width, frame.view.height);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer_);
    const float none[4] = {0.0f, 0.0f, 0.0f, 0.0f}, far = 1.0f;
    glClearNamedFramebufferfv(framebuffer_, GL_COLOR, 0, none);
    glClearNamedFramebufferfv(framebuffer_, GL_DEPTH, 0, &far);
    const GlProgram& p = normalsProgram_;
    glUseProgram(p.id());
    glUniformMatrix4fv(p.uniform("viewProjection"), 1, GL_FALSE, glm::value_ptr(frame.viewProjection));
    glBindTextureUnit(0, frame.targets.frontDepth());
    glUniform1i(p.uniform("frontDepth"), 0);
    if (frame.targets.cameraInside()) {
        glDisable(GL_CULL_FACE);  // a camera inside an object sees its back faces
    } else {
        glEnable(GL_CULL_FACE);
        glCullFace(GL_BACK);
    }
    glDisable(GL_BLEND);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    int slot = 0;
    for (size_t k = first; k < end; ++k) {
        const GpuObject& o = frame.objects[k];
        if (!o.surface) continue;
        glUniform1f(p.uniform("slot"), float(slot++));
        setMeshPlacement(p, o.placement);
        o.mesh->draw();
    }
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, frame.hostFramebuffer);
}

void SurfacePass::lightKeptFaces(const FrameContext& frame, size_t first, size_t end) const {
    std::array<glm::vec4, kBatch> diffuse{}, specularShininess{};
    int slot = 0;
    for (size_t k = first; k < end; ++k) {
        const GpuObject& o = frame.objects[k];
        if (!o.surface) continue;
        diffuse[slot] = glm::vec4(glm::vec3(o.surface->diffuse), 0.0f);
        specularShininess[slot] = glm::vec4(glm::vec3(o.surface->specular), float(o.surface->shininess));
        ++slot;
    }
    const GlProgram& p = surfaceProgram_;
    glUseProgram(p.id());
    glUniform1i(p.uniform("lightCount"), frame.lights.withEnvironment());
    glUniform3fv(p.uniform("cameraPosition"), 1, glm::value_ptr(frame.view.cameraPosition));
    const glm::mat4 inverse = glm::inverse(frame.viewProjection);
    glUniformMatrix4fv(p.uniform("inverseViewProjection"), 1, GL_FALSE, glm::value_ptr(inverse));
    glUniform2f(p.uniform("viewportSize"), float(frame.view.width), float(frame.view.height));
    glUniform4fv(p.uniform("diffuse"), slot, glm::value_ptr(diffuse[0]));
    glUniform4fv(p.uniform("specularShininess"), slot, glm::value_ptr(specularShininess[0]));
    glBindTextureUnit(0, normals_);
    glUniform1i(p.uniform("normals"), 0);
    glBindTextureUnit(1, depths_);
    glUniform1i(p.uniform("depths"), 1);
    glDisable(GL_CULL_FACE);
    glEnable(GL_DEPTH_TEST);  // against the host's depth, with the kept faces' own
    glDepthFunc(GL_LESS);
    glDepthMask(GL_FALSE);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE);
    glBindVertexArray(frame.targets.emptyVertexArray());
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

// The objects with a surface in batches of kBatch, each pixel lit once a batch.
void SurfacePass::drawSurfaces(FrameContext& frame) {
    size_t first = 0;
    while (first < frame.objects.size()) {
        size_t end = first;
        for (int withSurface = 0; end < frame.objects.size(); ++end) {
            if (!frame.objects[end].surface) continue;
            if (withSurface == kBatch) break;
            ++withSurface;
        }
        keepNearestFaces(frame, first, end);
        lightKeptFaces(frame, first, end);
        first = end;
    }
}

void SurfacePass::draw(FrameContext& frame) {
    const bool anySurface =
        std::any_of(frame.objects.begin(), frame.objects.end(), [](const GpuObject& o) { return bool(o.surface); });
    if (frame.options.surface && anySurface) drawSurfaces(frame);
}

}  // namespace lucent
