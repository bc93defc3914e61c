#pragma once
// Linear RGB radiance images and their file formats: PFM and EXR keep linear
// floats, PNG is tone-mapped to 8-bit sRGB for viewing.
#include <filesystem>
#include <vector>

#include <glm/glm.hpp>

namespace lucent {

struct Image {
    int width = 0, height = 0;
    std::vector<glm::vec3> pixels;  // row-major, row 0 at the top

    Image() = default;
    Image(int w, int h) : width(w), height(h), pixels(size_t(w) * h, glm::vec3(0.0f)) {}
    glm::vec3& at(int x, int y) { return pixels[size_t(y) * width + x]; }
    const glm::vec3& at(int x, int y) const { return pixels[size_t(y) * width + x]; }
};

// The extension picks the format (.png, .pfm, .exr). Non-finite or negative values
// are written as 0 so that nothing downstream ever sees NaN or Inf.
// For PNG, exposure scales radiance before the sRGB curve; exposure <= 0 picks one
// that maps the 99.5th percentile of luminance to white.
// The exposure that maps the 99.5th percentile of positive luminance to white
// (1 for an image with none): what PNG output and the viewer use by default.
float autoExposure(const Image& image);

void writeImage(const std::filesystem::path& file, const Image& image, float exposure = 0.0f);
Image readPfm(const std::filesystem::path& file);

}  // namespace lucent
