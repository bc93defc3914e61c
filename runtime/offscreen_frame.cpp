#include "runtime/offscreen_frame.h"

#include <algorithm>
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
    static_assert(sizeof(glm::vec3) == 3 * sizeof(float));
    Image image(width_, height_);
    glFinish();
    // Read as RGB straight into the image, not through an RGBA copy: 10 MB less
    // memory to touch at 800x800, where the first write to a page is what costs
    // (docs/runtime.md, "The whole command, and page faults"). A row of floats
    // needs no padding at the default pack alignment of 4.
    glGetTextureImage(colour_, 0, GL_RGB, GL_FLOAT, GLsizei(image.pixels.size() * sizeof(glm::vec3)),
                      image.pixels.data());
    const auto row = [&](int y) { return image.pixels.begin() + std::ptrdiff_t(y) * width_; };
    for (int y = 0; y < height_ / 2; ++y) std::swap_ranges(row(y), row(y + 1), row(height_ - 1 - y));  // GL rows start at the bottom
    for (glm::vec3& c : image.pixels)
        for (int k = 0; k < 3; ++k)
            if (!std::isfinite(c[k]) || c[k] < 0.0f) c[k] = 0.0f;
    return image;
}

}  // namespace lucent
