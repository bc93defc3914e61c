#pragma once
// A float colour target with a depth texture, read back as a linear Image or
// shown in a window.
#include <memory>

#include "core/image.h"
#include "runtime/opengl.h"

namespace lucent {

class OffscreenFrame {
public:
    OffscreenFrame(int width, int height);
    ~OffscreenFrame();
    OffscreenFrame(const OffscreenFrame&) = delete;
    OffscreenFrame& operator=(const OffscreenFrame&) = delete;

    void bindAndClear() const;  // colour to 0, depth to 1
    GlName depthTexture() const { return depth_; }
    GlName colourTexture() const { return colour_; }
    Image read() const;  // row 0 at the top; non-finite and negative values as 0
    // Adds image (row 0 at the top, the frame's size) to what the frame holds:
    // light found on the CPU, such as the environment's background.
    void add(const Image& image) const;

    // Shows the frame in the current context's default framebuffer (a window's
    // back buffer) of windowWidth x windowHeight: the window cleared to black,
    // then the frame with its lower-left corner at (x, y), its linear radiance
    // times exposure encoded as sRGB. For hosts that display Lucent's frame as
    // it is, as lucent view does.
    void present(int windowWidth, int windowHeight, int x, int y, float exposure) const;

private:
    struct Presenter;  // the display program, made on first use
    int width_, height_;
    GlName framebuffer_ = 0, colour_ = 0, depth_ = 0;
    mutable std::unique_ptr<Presenter> presenter_;
};

// The current context's default framebuffer (a window's back buffer) of
// width x height as shown, its sRGB decoded to linear radiance, row 0 at the top:
// writing it with exposure 1 encodes it again as it was shown.
Image readWindow(int width, int height);

}  // namespace lucent
