// The proxies that draw each Gaussian (runtime/internal/scatter.geom): the
// cut-off moves light and loses none, the point sprites keep it across the
// viewport's edge and past the largest point, and the render benchmark's
// fragment counts are pixels.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/error.h"

#include "preprocess/preprocessor.h"
#include "runtime/offscreen_context.h"
#include "runtime/offscreen_frame.h"
#include "runtime/scattering_renderer.h"
#include "tests/support/test_support.h"

namespace lucent {
namespace {

double totalGreen(const Image& image) {
    double sum = 0.0;
    for (const auto& p : image.pixels) sum += p.g;
    return sum;
}

// A box of thin medium seen from 4 units with one Gaussian 0.1 wide at its
// centre: its cut-off sphere (at most 4.8 widths at epsilon = 1e-5) stays 0.5
// inside every face, so every ray through it integrates it whole.
struct OneGaussian {
    OneGaussian() {
        scene.camera = test::squareCamera(Vec3(0, 0, 4), Vec3(0, 0, 0), 30.0, 128);
        scene.lights = {test::pointLight(Vec3(3, 3, 3), Rgb(40.0))};
        scene.objects = {test::simpleObject(test::writeBox(dir, "box.obj", Vec3(-1), Vec3(1)), 0.2, 0.8)};
        std::vector<std::string> warnings;
        objects = loadObjects(scene, warnings);
        PreprocessSettings settings = qualityPreset("draft");
        settings.samples = 1500;
        SampleSet set = preprocessObject(objects[0], settings);
        // Keep the sample nearest the centre alone, 0.1 wide, moved to the centre
        // exactly (its image with it), where the pixel figures below hold.
        size_t nearest = 0;
        for (size_t i = 1; i < set.size(); ++i)
            if (glm::length(set.positions[i]) < glm::length(set.positions[nearest])) nearest = i;
        if (!(glm::length(set.positions[nearest]) < 0.1f)) throw Error("no sample near the box's centre");
        one = set;
        one.positions = {glm::vec3(0.0f)};
        one.radii = {set.radii[nearest]};
        one.widths = {0.1f};
        one.weights = {set.weights[nearest]};
        one.extinction = {set.extinction[nearest]};
        one.region = {set.region[nearest]};
        one.image = {set.image[nearest] - set.positions[nearest]};
        one.boundary = {set.boundary[nearest]};
        one.truncationError = {set.truncationError[nearest]};
        const size_t n = set.coefficientsPerSample();
        const std::vector<float>& sh = set.coefficients();
        one.sh.assign(sh.begin() + std::ptrdiff_t(nearest * n), sh.begin() + std::ptrdiff_t((nearest + 1) * n));
    }
    // The image at this size (full resolution), or of its columns [0, columns);
    // with fragments, the proxies' fragments counted (DrawOptions::fragments).
    Image draw(int size, double cutoff, int columns = 0, ScatterFragments* fragments = nullptr) const {
        ViewSetup view = viewSetupFor(withSize(size), objects[0].mesh().bounds());
        if (columns > 0) {
            // The same camera's frustum cut to the window's first columns:
            // x_ndc' = (x_ndc + 1) size / columns - 1.
            glm::mat4 crop(1.0f);
            crop[0][0] = float(size) / float(columns);
            crop[3][0] = crop[0][0] - 1.0f;
            view.projection = crop * view.projection;
            view.width = columns;
        }
        OffscreenFrame frame(view.width, view.height);
        DrawOptions options;
        options.surface = false;
        options.scatterScale = 1;
        if (fragments) {
            options.fragments = fragments;
            options.discardBelow = float(cutoff);
        }
        ScatteringRenderer renderer(cutoff);
        renderer.addObject(translucentObjectFor(objects[0], one));
        renderer.setLights(scene.lights);
        frame.bindAndClear();
        renderer.draw(view, options);
        return frame.read();
    }
    Camera withSize(int size) const {
        Camera camera = scene.camera;
        camera.width = camera.height = size;
        return camera;
    }
    test::ScratchDir dir;
    SceneDesc scene;
    std::vector<VolumeObject> objects;
    SampleSet one;
};

// Seen on screen a Gaussian is a 2D Gaussian, and the square around the circle
// where it falls to epsilon of its peak (radius r = s sqrt(2 ln(1 / epsilon)))
// keeps erf(r / (s sqrt 2))^2 of its mass; the scattering pass scales what it
// keeps to the whole. The image's total light must not depend on epsilon.
// Without the scaling, epsilon = 0.1 would lose 6.6% of it (a scaling by
// 1 / (1 - epsilon), the circle's share, would add 3.8%).
TEST(GaussianCutoff, MovesLightButKeepsItsTotal) {
    const OneGaussian gaussian;
    const auto context = OffscreenContext::create(GlBackend::Auto);
    auto total = [&](double cutoff) { return totalGreen(gaussian.draw(128, cutoff)); };
    const double whole = total(1e-5);
    ASSERT_GT(whole, 0.0);
    // The tails' shape changes by the perspective's second order (the sphere
    // subtends 0.12 rad here): 1% holds it, and the missing scaling (10%) fails.
    const double coarse = total(0.1) / whole, defaultCutoff = total(1e-2) / whole;
    std::printf("total light against epsilon = 1e-5: %.4f at 0.1, %.4f at 1e-2\n", coarse, defaultCutoff);
    EXPECT_NEAR(coarse, 1.0, 0.01);
    EXPECT_NEAR(defaultCutoff, 1.0, 0.01);
}

// scatter.geom draws each Gaussian's proxy as point sprites where they cover the
// target, and GL drops a point whose centre lies outside the viewport: a
// Gaussian across the viewport's edge must still light the pixels inside. Cut to
// its first columns, the camera's image must be the full image's columns: the
// same rays meet the same Gaussian. At 600 pixels and the default epsilon 1e-2
// the proxy is one point 170 pixels wide, whose centre lies 10 pixels right of
// the cut at 290 columns (the columns left of it hold about a third of the
// light). Cut, the proxy's box is 75 by 170 pixels, and its point, 170 wide,
// also covers the 47 columns left of the box, where the Gaussian is below the
// cut-off: there the images may differ by up to epsilon of the peak, and hold
// 0.12% of the light (Phi(-3.03) - Phi(-4.7), the Gaussian 28 pixels wide).
TEST(GaussianCutoff, AProxyAcrossTheViewportsEdgeKeepsItsLightInside) {
    const OneGaussian gaussian;
    const auto context = OffscreenContext::create(GlBackend::Auto);
    const int size = 600, columns = 290;
    const Image full = gaussian.draw(size, 1e-2), cut = gaussian.draw(size, 1e-2, columns);
    ASSERT_EQ(cut.width, columns);
    // The Gaussian's peak, right of the cut: the columns' own brightest pixel
    // lies 10 pixels off it, 8% dimmer.
    double peak = 0.0, worst = 0.0, inside = 0.0;
    for (const auto& p : full.pixels) peak = std::max(peak, double(p.g));
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < columns; ++x) {
            const float a = full.pixels[size_t(y) * size + x].g, b = cut.pixels[size_t(y) * columns + x].g;
            worst = std::max(worst, double(std::abs(a - b)));
            inside += a;
        }
    ASSERT_GT(peak, 0.0);
    EXPECT_GT(inside, 0.25 * totalGreen(full)) << "the cut keeps a good part of the Gaussian";
    std::printf("cut: %.1f%% of the light, largest difference %.4f of the peak, total %.5f of the columns\n",
                100.0 * inside / totalGreen(full), worst / peak, totalGreen(cut) / inside);
    EXPECT_LE(worst, 1.01e-2 * peak);
    EXPECT_NEAR(totalGreen(cut) / inside, 1.0, 0.01);
}

// A proxy wider than the largest point (255 pixels on llvmpipe) is tiled with
// points; past kPointProxyTiles points of the largest size across the target,
// the proxies are squares of two triangles. The Gaussian at 1000 pixels (a proxy
// 282 pixels wide, two points across) and at 1100 (squares) must hold the same
// light per pixel area (1e-5 measured): one point of 255 pixels would lose the
// band between 2.7 and 3 sigma, 0.4% of it.
TEST(GaussianCutoff, PointsAndSquaresHoldTheSameLight) {
    const OneGaussian gaussian;
    const auto context = OffscreenContext::create(GlBackend::Auto);
    const double points = totalGreen(gaussian.draw(1000, 1e-2)) / (1000.0 * 1000.0);
    const double squares = totalGreen(gaussian.draw(1100, 1e-2)) / (1100.0 * 1100.0);
    ASSERT_GT(points, 0.0);
    std::printf("light per pixel area, squares at 1100 against points at 1000: %.6f\n", squares / points);
    EXPECT_NEAR(squares / points, 1.0, 1e-3);
}

// The render benchmark's useful fragments (DrawOptions::fragments) against a
// count by ray geometry. Every ray through this Gaussian integrates it whole, so
// its line integral peaks at the centre and is above epsilon of the peak exactly
// where the ray passes within r = s sqrt(2 ln(1 / epsilon)) of the centre: the
// kept fragments are the pixels whose centre ray does (1% for the shift by the
// light's variation, G' s^2, here 0.2 * 0.01 of s, and the disc's rim). The
// shaded ones are the proxy's pixels, a point sprite around that disc: at least
// its pixels and its corners (4 / pi of the disc, 1.15 asked), at most the disc's
// box and one more column and row for the rounding of the point's edges (1296 of
// 1369 here; llvmpipe's fragment shader invocations, counted in whole 4x4
// blocks, are 1440, and must be at least as many).
TEST(GaussianCutoff, FragmentCountsArePixels) {
    const OneGaussian gaussian;
    const auto context = OffscreenContext::create(GlBackend::Auto);
    const int size = 128;
    const double cutoff = 1e-2;
    ScatterFragments fragments;
    gaussian.draw(size, cutoff, 0, &fragments);
    const ViewSetup view = viewSetupFor(gaussian.withSize(size), gaussian.objects[0].mesh().bounds());
    const glm::dmat4 toWorld = glm::inverse(glm::dmat4(view.projection) * glm::dmat4(view.view));
    const Vec3 centre(gaussian.one.positions[0]);
    const double r = double(gaussian.one.widths[0]) * std::sqrt(2.0 * std::log(1.0 / cutoff));
    long long disc = 0;
    int x0 = size, x1 = -1, y0 = size, y1 = -1;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            const glm::dvec2 ndc(2.0 * (x + 0.5) / size - 1.0, 2.0 * (y + 0.5) / size - 1.0);
            const glm::dvec4 a = toWorld * glm::dvec4(ndc, -1.0, 1.0), b = toWorld * glm::dvec4(ndc, 1.0, 1.0);
            const Vec3 from = Vec3(a) / a.w, dir = glm::normalize(Vec3(b) / b.w - from);
            const Vec3 offset = centre - from;
            if (glm::length(offset - glm::dot(offset, dir) * dir) > r) continue;
            ++disc;
            x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
        }
    ASSERT_GT(disc, 1000) << "the disc spans tens of pixels";
    const double box = double(x1 - x0 + 2) * double(y1 - y0 + 2);
    std::printf("disc %lld pixels (its box and a row and column: %.0f); kept %llu, shaded %llu, invocations %llu\n",
                disc, box, fragments.kept, fragments.shaded, fragments.invocations);
    EXPECT_NEAR(double(fragments.kept) / double(disc), 1.0, 0.01);
    EXPECT_GE(double(fragments.shaded), 1.15 * double(disc));
    EXPECT_LE(double(fragments.shaded), box);
    EXPECT_GE(fragments.invocations, fragments.shaded);
}

}  // namespace
}  // namespace lucent
