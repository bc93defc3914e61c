#pragma once
// An environment light: radiance arriving from every direction, from an
// equirectangular HDR map (.hdr through stb_image, .exr through OpenEXR).
//
// The convention (docs/scene-file.md): row 0 is the top (+y). The texel at
// (u, v) in [0, 1]^2 holds the radiance arriving from the direction
//     (sin t cos p, cos t, -sin t sin p),  t = pi v,  p = 2 pi u,
// so u = 0 looks towards +x and u grows towards -z. The scene's "rotate" turns
// these directions into the world's, and "scale" multiplies the radiance.
//
// The map is piecewise constant over its texels, and it is sampled as such: a
// 2-D distribution over (u, v), half in proportion to each texel's mean channel
// times sin t (pbrt-v4's image infinite light does the same) and half to sin t
// alone (its solid angle), turned into a density over solid angle by the
// Jacobian 2 pi^2 sin t.
#include <filesystem>
#include <memory>
#include <vector>

#include "core/image.h"
#include "core/math.h"
#include "core/scene.h"
#include "core/similarity.h"

namespace lucent {

// Point k of a Hammersley set of count points in [0, 1)^2, shifted off the
// poles: well spread for any count, and the same every run.
glm::dvec2 stratifiedPoint(int k, int count);

class EnvironmentMap {
public:
    // pixels: the map as read (row 0 the top), every value finite and >= 0.
    EnvironmentMap(Image pixels, double scale, const glm::dmat3& rotation);

    // Reads desc.file; Error("FILE: problem") for anything but a readable,
    // finite, non-negative map within the size limits of docs/robustness.md.
    static std::shared_ptr<const EnvironmentMap> load(const EnvironmentDesc& desc);

    // The radiance arriving from the unit world direction toward (not travelling along it).
    Rgb radiance(const Vec3& toward) const;

    struct Sample {
        Vec3 toward{0.0};  // unit world direction the light comes from
        Rgb radiance{0.0};
        double pdf = 0.0;  // per steradian
    };
    // A direction drawn in proportion to the texels' radiance, from two uniform numbers.
    Sample sample(double u1, double u2) const;
    // The density per steradian with which sample() draws the direction toward.
    double pdf(const Vec3& toward) const;

    // count directions drawn by sample() from stratifiedPoint(k, count).
    std::vector<Sample> stratifiedSamples(int count) const;
    // The map as count directional lights that a method without its own
    // environment sampling renders: count directions drawn by sample() from a
    // stratified grid (deterministic), each with irradiance L / (pdf count), so
    // that their sum estimates the integral of L over the sphere against any smooth factor.
    std::vector<Light> asDirectionalLights(int count) const;

    int width() const { return width_; }
    int height() const { return height_; }
    double scale() const { return scale_; }  // what the file's texels were multiplied by

private:
    int texelOf(const Vec3& toward) const;  // the texel's index

    int width_ = 0, height_ = 0;
    double scale_ = 1.0;
    std::vector<Rgb> texels_;               // scaled radiance, row-major, row 0 the top
    glm::dmat3 rotation_{1.0};              // map directions to world directions
    std::vector<double> rowCdf_;            // height_ + 1 entries
    std::vector<double> columnCdf_;         // per row, width_ + 1 entries
    std::vector<double> texelProbability_;  // of each texel, sums to 1
};

// desc's map as count directional lights, appended to lights (every method
// without its own environment sampling renders the scene this way).
std::vector<Light> withEnvironmentLights(std::vector<Light> lights, const EnvironmentMap* environment, int count);

}  // namespace lucent
