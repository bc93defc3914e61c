#pragma once
// A float colour target with a depth texture, read back as a linear Image.
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
    Image read() const;         // row 0 at the top; non-finite and negative values as 0

private:
    int width_, height_;
    GlName framebuffer_ = 0, colour_ = 0, depth_ = 0;
};

}  // namespace lucent
