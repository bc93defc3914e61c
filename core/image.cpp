#include "core/image.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfOutputFile.h>
#include <png.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>

#include "core/atomic_file.h"
#include "core/error.h"

namespace lucent {
namespace {

glm::vec3 sanitized(glm::vec3 c) {
    for (int i = 0; i < 3; ++i)
        if (!std::isfinite(c[i]) || c[i] < 0.0f) c[i] = 0.0f;
    return c;
}

void writePfm(const std::filesystem::path& file, const Image& image) {
    AtomicFile out(file);
    auto& s = out.stream();
    s << "PF\n" << image.width << " " << image.height << "\n-1.0\n";  // negative scale: little endian
    // One write a row: a write a pixel made the stream's per-call cost the file's.
    std::vector<float> row(3 * size_t(image.width));
    for (int y = image.height - 1; y >= 0; --y) {  // PFM stores rows bottom to top
        for (int x = 0; x < image.width; ++x) {
            const glm::vec3 c = sanitized(image.at(x, y));
            std::copy(&c[0], &c[0] + 3, row.begin() + 3 * x);
        }
        s.write(reinterpret_cast<const char*>(row.data()), std::streamsize(row.size() * sizeof(float)));
    }
    out.commit();
}

void writeExr(const std::filesystem::path& file, const Image& image) {
    AtomicFile out(file);
    std::vector<glm::vec3> clean(image.pixels.size());
    std::transform(image.pixels.begin(), image.pixels.end(), clean.begin(), sanitized);
    try {
        Imf::Header header(image.width, image.height);
        for (const char* c : {"R", "G", "B"}) header.channels().insert(c, Imf::Channel(Imf::FLOAT));
        Imf::OutputFile exr(out.temporaryPath().c_str(), header);
        Imf::FrameBuffer frame;
        const size_t xStride = sizeof(glm::vec3), yStride = xStride * image.width;
        char* base = reinterpret_cast<char*>(clean.data());
        frame.insert("R", Imf::Slice(Imf::FLOAT, base + 0, xStride, yStride));
        frame.insert("G", Imf::Slice(Imf::FLOAT, base + 4, xStride, yStride));
        frame.insert("B", Imf::Slice(Imf::FLOAT, base + 8, xStride, yStride));
        exr.setFrameBuffer(frame);
        exr.writePixels(image.height);
    } catch (const std::exception& e) {
        throw Error(file.string(), std::string("cannot write EXR: ") + e.what());
    }
    out.commit();
}

// sRGB encoding (IEC 61966-2-1) to 8 bits.
unsigned char srgb8Formula(float linear) {
    linear = std::clamp(linear, 0.0f, 1.0f);
    const float s = linear <= 0.0031308f ? 12.92f * linear : 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
    return static_cast<unsigned char>(std::lround(s * 255.0f));
}

// The formula costs a pow per channel, a large share of writing a frame. It rises in
// 255 steps, found once by bisection over the floats (ordered as their bits when
// positive). The code at the start of each run of 2^14 floats (exponent and top
// 9 mantissa bits) is tabled; within a run the code rises by at most one step
// (0.2 at most, where sRGB is steepest per run), so one comparison with the next
// step gives the formula's code (checked on every 7th float up to 1: all equal).
class SrgbEncoder {
public:
    SrgbEncoder() {
        for (int code = 1; code <= 255; ++code) {
            uint32_t lo = 0, hi = kOne;  // the formula gives 255 at 1
            while (lo < hi) {
                const uint32_t mid = lo + (hi - lo) / 2;
                if (srgb8Formula(std::bit_cast<float>(mid)) >= code)
                    hi = mid;
                else
                    lo = mid + 1;
            }
            steps_[size_t(code - 1)] = std::bit_cast<float>(lo);
        }
        steps_[255] = std::numeric_limits<float>::infinity();
        for (uint32_t run = 0; run < runStart_.size(); ++run)
            runStart_[run] = srgb8Formula(std::bit_cast<float>(run << kRunBits));
    }
    // linear: finite or +infinity, not negative (sanitized).
    unsigned char operator()(float linear) const {
        const uint32_t bits = std::bit_cast<uint32_t>(linear);
        if (bits >= kOne) return 255;
        unsigned char code = runStart_[bits >> kRunBits];
        return linear >= steps_[code] ? code + 1 : code;
    }

private:
    static constexpr uint32_t kOne = 0x3f800000u;  // the bits of 1.0f
    static constexpr int kRunBits = 14;
    std::array<float, 256> steps_{};                            // the least float of each code 1..255
    std::array<unsigned char, (kOne >> kRunBits)> runStart_{};  // 65 KB
};

void writePng(const std::filesystem::path& file, const Image& image, float exposure) {
    if (!(exposure > 0.0f) || !std::isfinite(exposure)) exposure = autoExposure(image);
    static const SrgbEncoder toSrgb8;
    std::vector<unsigned char> rgb(size_t(image.width) * image.height * 3);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, image.pixels.size(), 4096),
                      [&](const tbb::blocked_range<size_t>& r) {
                          for (size_t i = r.begin(); i < r.end(); ++i) {
                              const glm::vec3 c = sanitized(image.pixels[i]) * exposure;
                              for (int k = 0; k < 3; ++k) rgb[3 * i + k] = toSrgb8(c[k]);
                          }
                      });
    AtomicFile out(file);
    out.stream().close();
    FILE* fp = std::fopen(out.temporaryPath().c_str(), "wb");
    if (!fp) throw Error(file.string(), "cannot write PNG");
    // libpng prints its errors itself unless given handlers: these keep the
    // message for Lucent's one error line.
    thread_local std::string pngMessage;
    pngMessage.clear();
    const auto onError = [](png_structp p, png_const_charp message) {
        pngMessage = message ? message : "unknown libpng error";
        png_longjmp(p, 1);
    };
    const auto onWarning = [](png_structp, png_const_charp) {};
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, onError, onWarning);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    if (!png || !info || setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        std::fclose(fp);
        throw Error(file.string(), "cannot write PNG" + (pngMessage.empty() ? std::string() : ": " + pngMessage));
    }
    png_init_io(png, fp);
    png_set_IHDR(png, info, png_uint_32(image.width), png_uint_32(image.height), 8, PNG_COLOR_TYPE_RGB,
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_set_sRGB(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
    // libpng's defaults (zlib level 6, every row filter tried) were most of the
    // time a frame took to write; level 1 with the Up filter is several times
    // faster for a file a quarter larger.
    png_set_compression_level(png, 1);
    png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_UP);
    png_write_info(png, info);
    for (int y = 0; y < image.height; ++y) png_write_row(png, rgb.data() + size_t(y) * image.width * 3);
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    const bool closed = std::fclose(fp) == 0;
    if (!closed) throw Error(file.string(), "cannot write PNG (disk full?)");
    out.commit();
}

}  // namespace

float autoExposure(const Image& image) {
    std::vector<float> luminance;
    luminance.reserve(image.pixels.size());
    for (const auto& p : image.pixels) {
        const glm::vec3 c = sanitized(p);
        const float l = 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b;
        if (l > 0.0f) luminance.push_back(l);
    }
    if (luminance.empty()) return 1.0f;
    const size_t k = std::min(luminance.size() - 1, size_t(0.995 * double(luminance.size())));
    std::nth_element(luminance.begin(), luminance.begin() + long(k), luminance.end());
    return 1.0f / luminance[k];
}

void writeImage(const std::filesystem::path& file, const Image& image, float exposure) {
    const std::string ext = file.extension().string();
    if (ext == ".pfm")
        writePfm(file, image);
    else if (ext == ".exr")
        writeExr(file, image);
    else if (ext == ".png")
        writePng(file, image, exposure);
    else
        throw Error(file.string(), "unknown image format '" + ext + "' (use .png, .pfm or .exr)");
}

Image readPfm(const std::filesystem::path& file) {
    const std::string name = file.string();
    std::ifstream in(file, std::ios::binary);
    if (!in) throw Error(name, "cannot open PFM file");
    std::string magic;
    int w = 0, h = 0;
    double scale = 0.0;
    in >> magic >> w >> h >> scale;
    in.get();
    if (magic != "PF" || w <= 0 || h <= 0 || scale >= 0.0) throw Error(name, "not a little-endian RGB PFM file");
    Image image(w, h);
    for (int y = h - 1; y >= 0; --y)
        for (int x = 0; x < w; ++x) in.read(reinterpret_cast<char*>(&image.at(x, y)[0]), 3 * sizeof(float));
    if (!in) throw Error(name, "PFM file is truncated");
    return image;
}

}  // namespace lucent
