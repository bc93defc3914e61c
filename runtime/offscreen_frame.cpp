#include "runtime/offscreen_frame.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "runtime/internal/gl.h"
#include "runtime/internal/gl_program.h"

namespace lucent {

struct OffscreenFrame::Presenter {
    GlProgram program{{GL_VERTEX_SHADER, "fullscreen.vert"}, {GL_FRAGMENT_SHADER, "present.frag"}};
    GLuint emptyVao = 0;
    Presenter() { glCreateVertexArrays(1, &emptyVao); }
    ~Presenter() { glDeleteVertexArrays(1, &emptyVao); }
};

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
    presenter_.reset();
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
    for (int y = 0; y < height_ / 2; ++y)
        std::swap_ranges(row(y), row(y + 1), row(height_ - 1 - y));  // GL rows start at the bottom
    for (glm::vec3& c : image.pixels)
        for (int k = 0; k < 3; ++k)
            if (!std::isfinite(c[k]) || c[k] < 0.0f) c[k] = 0.0f;
    return image;
}

void OffscreenFrame::add(const Image& image) const {
    if (image.width != width_ || image.height != height_)
        throw Error("OffscreenFrame::add: an image of " + std::to_string(image.width) + "x" +
                    std::to_string(image.height) + " added to a frame of " + std::to_string(width_) + "x" +
                    std::to_string(height_));
    Image sum = read();
    for (size_t p = 0; p < sum.pixels.size(); ++p) sum.pixels[p] += image.pixels[p];
    const auto row = [&](int y) { return sum.pixels.begin() + std::ptrdiff_t(y) * width_; };
    for (int y = 0; y < height_ / 2; ++y) std::swap_ranges(row(y), row(y + 1), row(height_ - 1 - y));
    glTextureSubImage2D(colour_, 0, 0, 0, width_, height_, GL_RGB, GL_FLOAT, sum.pixels.data());
}

void OffscreenFrame::present(int windowWidth, int windowHeight, int x, int y, float exposure) const {
    if (!presenter_) presenter_ = std::make_unique<Presenter>();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, windowWidth, windowHeight);
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glViewport(x, y, width_, height_);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    const GlProgram& program = presenter_->program;
    glUseProgram(program.id());
    glBindTextureUnit(0, colour_);
    glUniform1i(program.uniform("radiance"), 0);
    glUniform1f(program.uniform("exposure"), exposure);
    glUniform2i(program.uniform("offset"), x, y);
    glBindVertexArray(presenter_->emptyVao);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glUseProgram(0);
}

Image readWindow(int width, int height) {
    std::vector<float> rgb(size_t(width) * height * 3);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    glReadBuffer(GL_BACK);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGB, GL_FLOAT, rgb.data());
    Image image(width, height);
    auto linear = [](float c) { return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f); };
    for (int y = 0; y < height; ++y)  // GL rows start at the bottom
        for (int x = 0; x < width; ++x) {
            const float* p = &rgb[(size_t(height - 1 - y) * width + x) * 3];
            image.at(x, y) = glm::vec3(linear(p[0]), linear(p[1]), linear(p[2]));
        }
    return image;
}

}  // namespace lucent
