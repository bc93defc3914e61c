#include "runtime/internal/frame_targets.h"

#include <glm/gtc/type_ptr.hpp>

#include <bit>

#include "core/error.h"
#include "runtime/internal/placement_uniforms.h"

namespace lucent {
namespace {

// Whether p (object space) lies inside the object; its ray caster is built only
// for a point inside its bounds.
bool containsPoint(GpuObject& o, const Vec3& p) {
    if (!o.bounds.contains(p)) return false;
    if (!o.boundary) o.boundary = std::make_unique<MeshRaycaster>(*o.boundaryMesh);
    return o.boundary->contains(p);
}

}  // namespace

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

FrameTargets::~FrameTargets() {
    glDeleteVertexArrays(1, &emptyVao_);
    if (layerFramebuffer_) glDeleteFramebuffers(1, &layerFramebuffer_);
    if (layerArray_) glDeleteTextures(1, &layerArray_);
}

void FrameTargets::drawMeshes(const FrameContext& frame, const GlProgram& program) {
    for (const GpuObject& o : frame.objects) {
        setMeshPlacement(program, o.placement);
        o.mesh->draw();
    }
}

void FrameTargets::drawPeeled(const FrameContext& frame, bool firstIntervalOnly) {
    const int intervals = firstIntervalOnly ? 1 : gpu::kMaxRaySegments;
    // Where each pixel's ray enters the objects (nearest front face) and finally
    // leaves them (farthest back face).
    frontLayers_[0].clearDepth(1.0f);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, frontLayers_[0].framebuffer());
    glCullFace(GL_BACK);
    glDepthFunc(GL_LESS);
    drawMeshes(frame, depthProgram_);
    if (!firstIntervalOnly) {
        back_.clearDepth(0.0f);
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, back_.framebuffer());
        glCullFace(GL_FRONT);
        glDepthFunc(GL_GREATER);
        drawMeshes(frame, depthProgram_);
        glDepthFunc(GL_LESS);
    }
    if (frame.options.scattering) {
        // The later entries and the exits, nearest first, by depth peeling: each
        // layer keeps the nearest face beyond the layer before it. With the first
        // interval only, no layer has one before it, and the peeling program is
        // not even linked.
        for (int k = 0; k < gpu::kMaxRaySegments; ++k)
            for (const bool exits : {false, true}) {
                if (!exits && k == 0) continue;  // the nearest front face is drawn above
                if (k >= intervals) continue;    // no such interval: segment.frag reads none
                TextureTarget& layer = exits ? backLayers_[k] : frontLayers_[k];
                layer.clearDepth(1.0f);
                glBindFramebuffer(GL_DRAW_FRAMEBUFFER, layer.framebuffer());
                glCullFace(exits ? GL_FRONT : GL_BACK);
                // The first exit has no layer before it: the plain depth program keeps the nearest back face.
                const bool plain = exits && k == 0;
                const GlProgram& program = plain ? depthProgram_ : peelProgram_.get();
                glUseProgram(program.id());
                if (!plain) {
                    glUniformMatrix4fv(program.uniform("viewProjection"), 1, GL_FALSE,
                                       glm::value_ptr(frame.viewProjection));
                    glUniform1i(program.uniform("previousLayer"), 0);
                    glBindTextureUnit(0, (exits ? backLayers_[k - 1] : frontLayers_[k - 1]).texture());
                }
                drawMeshes(frame, program);
            }
    }
}

void FrameTargets::drawInOnePass(const FrameContext& frame, const ViewSetup& view) {
    constexpr GLsizei kLayers = 2 * gpu::kMaxRaySegments + 1;
    if (view.width != layerWidth_ || view.height != layerHeight_) {
        if (layerFramebuffer_) glDeleteFramebuffers(1, &layerFramebuffer_);
        if (layerArray_) glDeleteTextures(1, &layerArray_);
        glCreateTextures(GL_TEXTURE_2D_ARRAY, 1, &layerArray_);
        glTextureStorage3D(layerArray_, 1, GL_R32UI, view.width, view.height, kLayers);
        // An integer texture is complete only when nearest-filtered.
        glTextureParameteri(layerArray_, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTextureParameteri(layerArray_, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        glCreateFramebuffers(1, &layerFramebuffer_);
        glNamedFramebufferParameteri(layerFramebuffer_, GL_FRAMEBUFFER_DEFAULT_WIDTH, view.width);
        glNamedFramebufferParameteri(layerFramebuffer_, GL_FRAMEBUFFER_DEFAULT_HEIGHT, view.height);
        layerWidth_ = view.width;
        layerHeight_ = view.height;
    }
    // Nothing yet: the nearest faces at depth 1, the farthest at 0 (segment.frag's "none").
    const GLuint one = std::bit_cast<GLuint>(1.0f), zero = 0;
    glClearTexSubImage(layerArray_, 0, 0, 0, 0, view.width, view.height, kLayers - 1, GL_RED_INTEGER, GL_UNSIGNED_INT,
                       &one);
    glClearTexSubImage(layerArray_, 0, 0, 0, kLayers - 1, view.width, view.height, 1, GL_RED_INTEGER, GL_UNSIGNED_INT,
                       &zero);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, layerFramebuffer_);
    glDisable(GL_CULL_FACE);  // the fragment tells front from back (gl_FrontFacing)
    glDisable(GL_DEPTH_TEST);
    const GlProgram& layers = layersProgram_.get();
    glUseProgram(layers.id());
    glUniformMatrix4fv(layers.uniform("viewProjection"), 1, GL_FALSE, glm::value_ptr(frame.viewProjection));
    glBindImageTexture(0, layerArray_, 0, GL_TRUE, 0, GL_READ_WRITE, GL_R32UI);
    drawMeshes(frame, layers);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_CULL_FACE);
}

void FrameTargets::draw(const FrameContext& frame, const ViewSetup& view, Layers layers) {
    const bool firstIntervalOnly = layers == Layers::FirstInterval, onePass = layers == Layers::OnePass;
    const int intervals = firstIntervalOnly ? 1 : gpu::kMaxRaySegments;
    // Only the layers this frame draws: llvmpipe zeroes a texture's memory when
    // it is created, 2.6 MB a depth layer at 800x800.
    const bool scattering = frame.options.scattering;
    if (!onePass) {
        frontLayers_[0].resize(view.width, view.height);
        for (int k = 0; k < intervals && scattering; ++k) {
            frontLayers_[k].resize(view.width, view.height);
            backLayers_[k].resize(view.width, view.height);
        }
        if (!firstIntervalOnly) back_.resize(view.width, view.height);
    }
    host_.resize(view.width, view.height);
    if (scattering) inside_.resize(view.width, view.height);
    if (scattering && !firstIntervalOnly) {
        segments_.resize(view.width, view.height);
        reach_.resize(view.width, view.height);
    }
    // A camera inside an object sees no front face in front of it: its rays start inside.
    cameraInside_ = false;
    for (GpuObject& o : frame.objects)
        cameraInside_ = cameraInside_ || containsPoint(o, o.placement.inversePoint(Vec3(view.cameraPosition)));
    glViewport(0, 0, view.width, view.height);
    glDisable(GL_BLEND);
    glEnable(GL_DEPTH_TEST);
    glDepthMask(GL_TRUE);

    // The host's depth, copied so that no pass samples a texture it draws into.
    host_.clearDepth(1.0f);
    if (frame.options.hostDepthTexture) {
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, host_.framebuffer());
        glDepthFunc(GL_ALWAYS);
        const GlProgram& copy = copyDepthProgram_.get();
        glUseProgram(copy.id());
        glBindTextureUnit(0, frame.options.hostDepthTexture);
        glUniform1i(copy.uniform("source"), 0);
        glUniform2f(copy.uniform("sourcePerPixel"), float(frame.view.width) / float(view.width),
                    float(frame.view.height) / float(view.height));
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
    for (const GpuObject& o : frame.objects) {
        setMeshPlacement(depthProgram_, o.placement);
        for (const auto& blocker : o.blockers) blocker->draw();
    }

    if (onePass) {
        if (scattering) drawInOnePass(frame, view);
    } else {
        drawPeeled(frame, firstIntervalOnly);
    }
    glCullFace(GL_BACK);

    // Each pixel's ray segment inside the objects, once, so that the scattering
    // fragments read one texel instead of three depths and three unprojections.
    if (!scattering) return;
    const glm::mat4 inverseProjection = glm::inverse(view.projection);
    glDisable(GL_CULL_FACE);
    if (firstIntervalOnly) {
        // Only inside is read: segment.frag's segment and reach go nowhere, and
        // their targets are not even created (7.7 MB at 800x800).
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, inside_.framebuffer());
        const GLenum outputs[2] = {GL_NONE, GL_COLOR_ATTACHMENT0};
        glNamedFramebufferDrawBuffers(inside_.framebuffer(), 2, outputs);
        glDisable(GL_DEPTH_TEST);
    } else {
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, segments_.framebuffer());
        glDepthFunc(GL_ALWAYS);  // segment.frag writes the reach of every pixel
        glNamedFramebufferTexture(segments_.framebuffer(), GL_COLOR_ATTACHMENT1, inside_.texture(), 0);
        glNamedFramebufferTexture(segments_.framebuffer(), GL_DEPTH_ATTACHMENT, reach_.texture(), 0);
        const GLenum outputs[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
        glNamedFramebufferDrawBuffers(segments_.framebuffer(), 2, outputs);
    }
    const GlProgram& p = firstIntervalOnly ? segmentPrograms_.get({"FIRST_INTERVAL_ONLY"})
                         : onePass         ? segmentPrograms_.get({"ONE_PASS_LAYERS"})
                                           : segmentPrograms_.get();
    glUseProgram(p.id());
    glUniformMatrix4fv(p.uniform("inverseProjection"), 1, GL_FALSE, glm::value_ptr(inverseProjection));
    glUniform2f(p.uniform("viewportSize"), float(view.width), float(view.height));
    glUniform1i(p.uniform("cameraInside"), cameraInside_ ? 1 : 0);
    glBindTextureUnit(0, back_.texture());
    glBindTextureUnit(1, host_.texture());
    glUniform1i(p.uniform("farthestBack"), 0);
    glUniform1i(p.uniform("hostDepth"), 1);
    if (onePass) {
        glBindTextureUnit(2, layerArray_);
        glUniform1i(p.uniform("layers"), 2);
    } else {
        GLint units[2][gpu::kMaxRaySegments];
        for (int k = 0; k < gpu::kMaxRaySegments; ++k) {
            units[0][k] = 2 + k;
            units[1][k] = 2 + gpu::kMaxRaySegments + k;
            glBindTextureUnit(GLuint(units[0][k]), frontLayers_[k].texture());
            glBindTextureUnit(GLuint(units[1][k]), backLayers_[k].texture());
        }
        glUniform1iv(p.uniform("frontLayers"), gpu::kMaxRaySegments, units[0]);
        glUniform1iv(p.uniform("backLayers"), gpu::kMaxRaySegments, units[1]);
    }
    glBindVertexArray(emptyVao_);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
}

}  // namespace lucent
