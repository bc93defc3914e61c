#include "runtime/offscreen_frame.h"

#include <cmath>

#include "core/error.h"
#include "runtime/internal/gl.h"

namespace lucent {

OffscreenFrame::OffscreenFrame(int width, int height) : width_(width), height_(height) {
    GLint maxSize = 0;
    glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &maxSize);
    if (width > maxSize || height > maxSize)
        throw Error("image of " + std::to_string(width) + "x" + std::to_string(height) +
                    " exceeds this OpenGL's limit of " + std::to_string(maxSize));
    glCreateTextures(GL_TEXTURE_2D, 1, &colour_);
    glTextureStorage2D(colour_, 1, GL_RGBA32F, width, height);
    glCreateTextures(GL_TEXTURE_2D, 1, &depth_);
    glTextureStorage2D(depth_, 1, GL_DEPTH_COMPONENT32F, width, height);
    glTextureParameteri(depth_, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(depth_, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glCreateFramebuffers(1, &framebuffer_);
    glNamedFramebufferTexture(framebuffer_, GL_COLOR_ATTACHMENT0, colour_, 0);
    glNamedFramebufferTexture(framebuffer_, GL_DEPTH_ATTACHMENT, depth_, 0);
    if (glCheckNamedFramebufferStatus(framebuffer_, GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw Error("OpenGL: float framebuffer is incomplete (no RGBA32F render target?)");
}

OffscreenFrame::~OffscreenFrame() {
    glDeleteFramebuffers(1, &framebuffer_);
    glDeleteTextures(1, &colour_);
    glDeleteTextures(1, &depth_);
}

void OffscreenFrame::bindAndClear() const {
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
    const float black[4] = {0, 0, 0, 0}, far = 1.0f;
    glClearNamedFramebufferfv(framebuffer_, GL_COLOR, 0, black);
    glClearNamedFramebufferfv(framebuffer_, GL_DEPTH, 0, &far);
}

Image OffscreenFrame::read() const {
    std::vector<float> rgba(size_t(width_) * height_ * 4);
    glFinish();
    glGetTextureImage(colour_, 0, GL_RGBA, GL_FLOAT, GLsizei(rgba.size() * sizeof(float)), rgba.data());
    Image image(width_, height_);
    for (int y = 0; y < height_; ++y)
        for (int x = 0; x < width_; ++x) {
            const float* p = &rgba[(size_t(height_ - 1 - y) * width_ + x) * 4];  // GL rows start at the bottom
            glm::vec3 c(p[0], p[1], p[2]);
            for (int k = 0; k < 3; ++k)
                if (!std::isfinite(c[k]) || c[k] < 0.0f) c[k] = 0.0f;
            image.at(x, y) = c;
        }
    return image;
}

}  // namespace lucent
