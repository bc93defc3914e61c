#include "core/environment_map.h"

#include <ImfArray.h>
#include <ImfRgbaFile.h>
#include <stb_image.h>

#include <algorithm>
#include <cmath>
#include <fstream>

#include "core/error.h"
#include "core/input_file.h"
#include "core/limits.h"

namespace lucent {
namespace {

// Texels per side: a 16k x 8k map is already finer than any light needs
// (docs/robustness.md); the memory budget bounds the product.
constexpr int kMaxMapSide = 16384;
// Bytes the map costs per texel once loaded: the radiance (3 doubles), the
// probability and the column CDF, and the float copy read from the file.
constexpr uint64_t kBytesPerTexel = 3 * 8 + 8 + 8 + 12;

void checkDimensions(const std::filesystem::path& file, int64_t width, int64_t height) {
    if (width < 1 || height < 1 || width > kMaxMapSide || height > kMaxMapSide)
        throw Error(file.string(), "environment map of " + std::to_string(width) + " x " + std::to_string(height) +
                                       " texels; each side must be 1 to " + std::to_string(kMaxMapSide));
    checkMemoryBudget(uint64_t(width) * uint64_t(height) * kBytesPerTexel, file, "environment map");
}

// stb_image reads past the end of a short Radiance file as zeros, a silently
// black band: so the scanlines are walked first, each flat (4 bytes a texel)
// or run-length encoded (4 channels of runs, Greg Ward's format), and a file
// that ends before its last texel is refused.
void checkRadianceScanlines(const std::filesystem::path& file, const std::vector<unsigned char>& bytes, int width,
                            int height) {
    // The data begins after the blank line that ends the header and the resolution line after it.
    size_t at = 0;
    for (size_t i = 1; i < bytes.size(); ++i)
        if (bytes[i] == '\n' && bytes[i - 1] == '\n') {
            at = i + 1;
            break;
        }
    while (at < bytes.size() && bytes[at] != '\n') ++at;
    ++at;
    const auto truncated = [&] { throw Error(file.string(), "Radiance HDR file ends before its last texel"); };
    for (int y = 0; y < height; ++y) {
        if (at + 4 > bytes.size()) truncated();
        const bool encoded = width >= 8 && width < 32768 && bytes[at] == 2 && bytes[at + 1] == 2 &&
                             (bytes[at + 2] << 8 | bytes[at + 3]) == width;
        if (!encoded) {
            if (at + 4 * size_t(width) > bytes.size()) truncated();
            at += 4 * size_t(width);
            continue;
        }
        at += 4;
        for (int channel = 0; channel < 4; ++channel)
            for (int x = 0; x < width;) {
                if (at >= bytes.size()) truncated();
                const int count = bytes[at++];
                const int run = count > 128 ? count - 128 : count;
                if (run == 0 || x + run > width) throw Error(file.string(), "corrupt Radiance HDR scanline");
                at += count > 128 ? 1 : size_t(run);
                if (at > bytes.size()) truncated();
                x += run;
            }
    }
}

Image readRadianceHdr(const std::filesystem::path& file) {
    const uint64_t size = regularFileSize(file, "environment map");
    if (size > uint64_t(INT32_MAX)) throw Error(file.string(), "environment map file larger than 2 GiB");
    std::vector<unsigned char> bytes(size);
    std::ifstream in(file, std::ios::binary);
    if (!in.read(reinterpret_cast<char*>(bytes.data()), std::streamsize(size)))
        throw Error(file.string(), "cannot read environment map");
    const int length = int(size);
    if (!stbi_is_hdr_from_memory(bytes.data(), length)) throw Error(file.string(), "not a Radiance HDR (RGBE) file");
    int width = 0, height = 0, channels = 0;
    if (!stbi_info_from_memory(bytes.data(), length, &width, &height, &channels))
        throw Error(file.string(), std::string("unreadable Radiance HDR header: ") + stbi_failure_reason());
    checkDimensions(file, width, height);
    checkRadianceScanlines(file, bytes, width, height);
    float* data = stbi_loadf_from_memory(bytes.data(), length, &width, &height, &channels, 3);
    if (!data) throw Error(file.string(), std::string("cannot decode Radiance HDR: ") + stbi_failure_reason());
    Image image(width, height);
    for (size_t i = 0; i < image.pixels.size(); ++i)
        image.pixels[i] = glm::vec3(data[3 * i], data[3 * i + 1], data[3 * i + 2]);
    stbi_image_free(data);
    return image;
}

Image readOpenExr(const std::filesystem::path& file) {
    regularFileSize(file, "environment map");
    try {
        Imf::RgbaInputFile exr(file.c_str());
        const Imath::Box2i window = exr.dataWindow();
        const int64_t width = int64_t(window.max.x) - window.min.x + 1;
        const int64_t height = int64_t(window.max.y) - window.min.y + 1;
        checkDimensions(file, width, height);
        Imf::Array2D<Imf::Rgba> rows(height, width);
        exr.setFrameBuffer(&rows[0][0] - window.min.x - window.min.y * width, 1, size_t(width));
        exr.readPixels(window.min.y, window.max.y);
        Image image{int(width), int(height)};
        for (int y = 0; y < image.height; ++y)
            for (int x = 0; x < image.width; ++x) {
                const Imf::Rgba& p = rows[y][x];
                image.at(x, y) = glm::vec3(float(p.r), float(p.g), float(p.b));
            }
        return image;
    } catch (const Error&) {
        throw;
    } catch (const std::exception& e) {
        throw Error(file.string(), std::string("cannot read OpenEXR environment map: ") + e.what());
    }
}

// Where x falls in a CDF of n + 1 entries rising from 0 to 1: the bin and the offset within it.
int findBin(const std::vector<double>& cdf, size_t first, int n, double x, double* within) {
    const auto begin = cdf.begin() + std::ptrdiff_t(first);
    int bin = int(std::upper_bound(begin, begin + n + 1, x) - begin) - 1;
    bin = std::clamp(bin, 0, n - 1);
    // Skip bins of zero probability (a step of the CDF of zero width).
    while (bin < n - 1 && !(begin[bin + 1] > begin[bin])) ++bin;
    const double width = begin[bin + 1] - begin[bin];
    *within = width > 0.0 ? std::clamp((x - begin[bin]) / width, 0.0, 1.0) : 0.5;
    return bin;
}

double radicalInverseBase2(uint32_t k) {
    uint32_t bits = k;
    bits = (bits << 16) | (bits >> 16);
    bits = ((bits & 0x55555555u) << 1) | ((bits & 0xAAAAAAAAu) >> 1);
    bits = ((bits & 0x33333333u) << 2) | ((bits & 0xCCCCCCCCu) >> 2);
    bits = ((bits & 0x0F0F0F0Fu) << 4) | ((bits & 0xF0F0F0F0u) >> 4);
    bits = ((bits & 0x00FF00FFu) << 8) | ((bits & 0xFF00FF00u) >> 8);
    return double(bits) * 0x1p-32;
}

}  // namespace

EnvironmentMap::EnvironmentMap(Image pixels, double scale, const glm::dmat3& rotation)
    : width_(pixels.width), height_(pixels.height), scale_(scale), rotation_(rotation) {
    texels_.resize(size_t(width_) * height_);
    texelProbability_.resize(texels_.size());
    double total = 0.0;
    for (int y = 0; y < height_; ++y) {
        // sin t at the row's centre: the solid angle a texel of the row spans.
        const double sinTheta = std::sin(kPi * (y + 0.5) / height_);
        for (int x = 0; x < width_; ++x) {
            const size_t i = size_t(y) * width_ + x;
            texels_[i] = scale * Rgb(pixels.pixels[i]);
            texelProbability_[i] = (texels_[i].r + texels_[i].g + texels_[i].b) / 3.0 * sinTheta;
            total += texelProbability_[i];
        }
    }
    // Half the directions in proportion to the radiance, half to the solid angle
    // (defensive importance sampling, Hesterberg 1995): a bright sun must not
    // leave the rest of the sky, which lights whatever the sun does not, with a
    // handful of directions.
    const double byRadiance = total > 0.0 ? 0.5 : 0.0;  // a black map: by solid angle alone
    double solidAngle = 0.0;
    for (int y = 0; y < height_; ++y) solidAngle += width_ * std::sin(kPi * (y + 0.5) / height_);
    for (int y = 0; y < height_; ++y)
        for (int x = 0; x < width_; ++x) {
            double& p = texelProbability_[size_t(y) * width_ + x];
            p = (byRadiance > 0.0 ? byRadiance * p / total : 0.0) +
                (1.0 - byRadiance) * std::sin(kPi * (y + 0.5) / height_) / solidAngle;
        }
    rowCdf_.assign(size_t(height_) + 1, 0.0);
    columnCdf_.assign(size_t(height_) * (width_ + 1), 0.0);
    for (int y = 0; y < height_; ++y) {
        double row = 0.0;
        double* cdf = &columnCdf_[size_t(y) * (width_ + 1)];
        for (int x = 0; x < width_; ++x) cdf[x + 1] = row += texelProbability_[size_t(y) * width_ + x];
        for (int x = 1; x <= width_; ++x) cdf[x] = row > 0.0 ? cdf[x] / row : double(x) / width_;
        rowCdf_[y + 1] = rowCdf_[y] + row;
    }
    for (double& c : rowCdf_) c /= rowCdf_.back();
}

std::shared_ptr<const EnvironmentMap> EnvironmentMap::load(const EnvironmentDesc& desc) {
    regularFileSize(desc.file, "environment map");
    const std::string ext = desc.file.extension().string();
    Image pixels;
    if (ext == ".hdr")
        pixels = readRadianceHdr(desc.file);
    else if (ext == ".exr")
        pixels = readOpenExr(desc.file);
    else
        throw Error(desc.file.string(), "unknown environment map format '" + ext + "' (use .hdr or .exr)");
    for (size_t i = 0; i < pixels.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            const float v = pixels.pixels[i][c];
            const std::string texel = "environment map texel (" + std::to_string(i % pixels.width) + ", " +
                                      std::to_string(i / pixels.width) + ")";
            if (!std::isfinite(v) || v < 0.0f) throw Error(desc.file.string(), texel + " is negative or not finite");
            // The images and the GPU's lights hold single-precision floats (docs/robustness.md).
            if (double(v) * desc.scale > kMaxMagnitude)
                throw Error(desc.file.string(), texel + " times the scale exceeds 1e30");
        }
    return std::make_shared<const EnvironmentMap>(std::move(pixels), desc.scale, desc.rotation);
}

int EnvironmentMap::texelOf(const Vec3& toward) const {
    const Vec3 d = glm::transpose(rotation_) * toward;
    const double theta = std::acos(std::clamp(d.y, -1.0, 1.0));
    double phi = std::atan2(-d.z, d.x);
    if (phi < 0.0) phi += 2.0 * kPi;
    const int x = std::clamp(int(phi / (2.0 * kPi) * width_), 0, width_ - 1);
    const int y = std::clamp(int(theta / kPi * height_), 0, height_ - 1);
    return y * width_ + x;
}

Rgb EnvironmentMap::radiance(const Vec3& toward) const { return texels_[size_t(texelOf(toward))]; }

EnvironmentMap::Sample EnvironmentMap::sample(double u1, double u2) const {
    double dv, du;
    const int y = findBin(rowCdf_, 0, height_, u2, &dv);
    const int x = findBin(columnCdf_, size_t(y) * (width_ + 1), width_, u1, &du);
    const double theta = kPi * (y + dv) / height_, phi = 2.0 * kPi * (x + du) / width_;
    const double sinTheta = std::sin(theta);
    Sample s;
    s.toward = rotation_ * Vec3(sinTheta * std::cos(phi), std::cos(theta), -sinTheta * std::sin(phi));
    s.radiance = texels_[size_t(y) * width_ + x];
    // The texel's probability spread over its (u, v) area, per steradian.
    const double perUv = texelProbability_[size_t(y) * width_ + x] * width_ * height_;
    s.pdf = sinTheta > 0.0 ? perUv / (2.0 * kPi * kPi * sinTheta) : 0.0;
    return s;
}

double EnvironmentMap::pdf(const Vec3& toward) const {
    const int i = texelOf(toward);
    const Vec3 d = glm::transpose(rotation_) * toward;
    const double sinTheta = std::sqrt(std::max(0.0, 1.0 - d.y * d.y));
    if (!(sinTheta > 0.0)) return 0.0;
    return texelProbability_[size_t(i)] * width_ * height_ / (2.0 * kPi * kPi * sinTheta);
}

glm::dvec2 stratifiedPoint(int k, int count) {
    return {(k + 0.5) / count, std::fmod(radicalInverseBase2(uint32_t(k)) + 0.5 / count, 1.0)};
}

std::vector<EnvironmentMap::Sample> EnvironmentMap::stratifiedSamples(int count) const {
    std::vector<Sample> out;
    for (int k = 0; k < count; ++k) {
        const glm::dvec2 u = stratifiedPoint(k, count);
        out.push_back(sample(u.x, u.y));
    }
    return out;
}

std::vector<Light> EnvironmentMap::asDirectionalLights(int count) const {
    std::vector<Light> lights;
    for (const Sample& s : stratifiedSamples(count)) {
        // A black direction adds nothing but its cost.
        if (!(s.pdf > 0.0) || std::max({s.radiance.r, s.radiance.g, s.radiance.b}) <= 0.0) continue;
        Light l;
        l.type = Light::Type::Directional;
        l.direction = -s.toward;
        l.power = s.radiance / (s.pdf * count);
        lights.push_back(l);
    }
    return lights;
}

std::vector<Light> withEnvironmentLights(std::vector<Light> lights, const EnvironmentMap* environment, int count) {
    if (!environment) return lights;
    const std::vector<Light> more = environment->asDirectionalLights(count);
    lights.insert(lights.end(), more.begin(), more.end());
    return lights;
}

}  // namespace lucent
