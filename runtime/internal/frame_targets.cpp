#include "runtime/internal/frame_targets.h"

#include <glm/gtc/type_ptr.hpp>

#include "core/error.h"

namespace lucent {

void TextureTarget::resize(int width, int height) {
    if (width == width_ && height == height_) return;
    release();
    width_ = width;
    height_ = height;
    glCreateTextures(GL_TEXTURE_2D, 1, &texture_);
    glTextureStorage2D(texture_, 1, format_, width, height);
    glTextureParameteri(texture_, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(texture_, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glCreateFramebuffers(1, &framebuffer_);
    glNamedFramebufferTexture(framebuffer_, isDepth() ? GL_DEPTH_ATTACHMENT : GL_COLOR_ATTACHMENT0, texture_, 0);
    if (isDepth()) glNamedFramebufferDrawBuffer(framebuffer_, GL_NONE);
    if (glCheckNamedFramebufferStatus(framebuffer_, GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw Error("OpenGL: an internal framebuffer is incomplete");
}

void TextureTarget::release() {
    if (framebuffer_) glDeleteFramebuffers(1, &framebuffer_);
    if (texture_) glDeleteTextures(1, &texture_);
    framebuffer_ = texture_ = 0;
    width_ = height_ = 0;
}

FrameTargets::FrameTargets() { glCreateVertexArrays(1, &emptyVao_); }

FrameTargets::~FrameTargets() { glDeleteVertexArrays(1, &emptyVao_); }

void FrameTargets::drawMeshes(const FrameContext& frame) {
    for (const GpuObject& o : frame.objects) o.mesh->draw();
}

void FrameTargets::draw(const FrameContext& frame) {
    const ViewSetup& view = frame.view;
    front_.resize(view.width, view.height);
    back_.resize(view.width, view.height);
    host_.resize(view.width, view.height);
    segments_.resize(view.width, view.height);
    glViewport(0, 0, view.width, view.height);
    glDisable(GL_BLEND);
    glEnable(GL_DEPTH_TEST);
    glDepthMask(GL_TRUE);

    // The host's depth, copied so that no pass samples a texture it draws into.
    host_.clearDepth(1.0f);
    if (frame.options.hostDepthTexture) {
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, host_.framebuffer());
        glDepthFunc(GL_ALWAYS);
        glUseProgram(copyDepthProgram_.id());
        glBindTextureUnit(0, frame.options.hostDepthTexture);
        glUniform1i(copyDepthProgram_.uniform("source"), 0);
        glBindVertexArray(emptyVao_);
        glDrawArrays(GL_TRIANGLES, 0, 3);
    }
    // Blockers are opaque: the camera's rays stop at their front faces as at the host's geometry.
    glEnable(GL_CULL_FACE);
    glCullFace(GL_BACK);
    glDepthFunc(GL_LESS);
    glUseProgram(depthProgram_.id());
    glUniformMatrix4fv(depthProgram_.uniform("viewProjection"), 1, GL_FALSE, glm::value_ptr(frame.viewProjection));
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, host_.framebuffer());
    for (const GpuObject& o : frame.objects)
        for (const auto& blocker : o.blockers) blocker->draw();

    // Where each pixel's ray enters the objects (nearest front face) and finally
    // leaves them (farthest back face).
    front_.clearDepth(1.0f);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, front_.framebuffer());
    glCullFace(GL_BACK);
    glDepthFunc(GL_LESS);
    drawMeshes(frame);
    back_.clearDepth(0.0f);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, back_.framebuffer());
    glCullFace(GL_FRONT);
    glDepthFunc(GL_GREATER);
    drawMeshes(frame);
    glCullFace(GL_BACK);
    glDepthFunc(GL_LESS);

    // Each pixel's ray segment inside the objects, once, so that the scattering
    // fragments read one texel instead of three depths and three unprojections.
    if (!frame.options.scattering) return;
    const glm::mat4 inverseProjection = glm::inverse(view.projection);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, segments_.framebuffer());
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    const GlProgram& p = segmentProgram_;
    glUseProgram(p.id());
    glUniformMatrix4fv(p.uniform("inverseProjection"), 1, GL_FALSE, glm::value_ptr(inverseProjection));
    glUniform2f(p.uniform("viewportSize"), float(view.width), float(view.height));
    // A camera inside an object sees no front face in front of it: its rays start inside.
    bool cameraInside = false;
    for (const GpuObject& o : frame.objects)
        cameraInside = cameraInside || o.boundary->contains(Vec3(view.cameraPosition));
    glUniform1i(p.uniform("cameraInside"), cameraInside ? 1 : 0);
    glBindTextureUnit(0, front_.texture());
    glBindTextureUnit(1, back_.texture());
    glBindTextureUnit(2, host_.texture());
    glUniform1i(p.uniform("frontDepth"), 0);
    glUniform1i(p.uniform("backDepth"), 1);
    glUniform1i(p.uniform("hostDepth"), 2);
    glBindVertexArray(emptyVao_);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glEnable(GL_DEPTH_TEST);
}

}  // namespace lucent
