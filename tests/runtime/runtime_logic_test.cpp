// The runtime's pure logic, tested without a GL context (Magnum's first tier):
// the view setup against core's camera rays, shader source assembly, the sample
// records against gpu_layout.h, the slab table, the blocker shadow views, and
// the sample counts a GL's limits hold.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <cstddef>
#include <map>
#include <string>

#include "core/camera_rays.h"
#include "core/error.h"
#include "runtime/internal/blocker_shadow_views.h"
#include "runtime/internal/gpu_layout.h"
#include "runtime/internal/gpu_samples.h"
#include "runtime/internal/sample_packing.h"
#include "runtime/scattering_renderer.h"
#include "runtime/internal/shader_source.h"
#include "runtime/view_setup.h"

namespace lucent {
namespace {

// Pixel (px, py), row 0 at the top, where the rasteriser puts world point p.
glm::dvec2 projectToPixel(const ViewSetup& v, const Vec3& p) {
    const glm::dvec4 clip = glm::dmat4(v.projection) * glm::dmat4(v.view) * glm::dvec4(p, 1.0);
    const glm::dvec2 ndc = glm::dvec2(clip) / clip.w;
    return {(ndc.x + 1.0) * 0.5 * v.width, (1.0 - ndc.y) * 0.5 * v.height};
}

// Past GL_MAX_TEXTURE_BUFFER_SIZE a shader reads zeros: the set is refused
// instead. The limits are llvmpipe's (2^27 texels, 2^27 bytes of storage block).
TEST(GpuCapacity, RefusesSampleSetsPastTheGlLimitsAndTakesThoseAtThem) {
    const uint64_t limit = uint64_t(1) << 27, plenty = uint64_t(1) << 40;
    // Order 8, three channels: 192 coefficients a sample; 2^27 / 192 = 699 050.7.
    EXPECT_NO_THROW(checkGpuCapacity(699050, 192, limit, plenty));
    try {
        checkGpuCapacity(699051, 192, limit, plenty);
        ADD_FAILURE() << "699 051 samples of 192 coefficients passed a 2^27-texel limit";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("--sh-order"), std::string::npos) << e.what();
    }
    // The 96-byte sample records: 2^27 / 96 = 1 398 101.3.
    EXPECT_NO_THROW(checkGpuCapacity(1398101, 1, plenty, limit));
    EXPECT_THROW(checkGpuCapacity(1398102, 1, plenty, limit), Error);
}

TEST(ViewSetup, ProjectsAlongCoreCameraRays) {
    Camera camera;
    camera.position = Vec3(1.0, 2.0, 6.0);
    camera.target = Vec3(0.2, -0.1, 0.3);
    camera.up = Vec3(0.1, 1.0, 0.0);
    camera.fovYDegrees = 35.0;
    camera.width = 320;
    camera.height = 200;
    Bounds3 scene;
    scene.extend(Vec3(-1.0));
    scene.extend(Vec3(1.0));
    const ViewSetup view = viewSetupFor(camera, scene);
    const CameraRays rays(camera);
    for (const glm::dvec2 pixel : {glm::dvec2(0.5, 0.5), glm::dvec2(160.0, 100.0), glm::dvec2(300.25, 17.75)}) {
        const Vec3 p = rays.origin() + 4.0 * rays.direction(pixel.x, pixel.y);
        const glm::dvec2 back = projectToPixel(view, p);
        EXPECT_NEAR(back.x, pixel.x, 1e-3);
        EXPECT_NEAR(back.y, pixel.y, 1e-3);
    }
}

TEST(ViewSetup, DepthRangeEnclosesTheScene) {
    Camera camera;  // at (0, 0, 5) looking at the origin
    Bounds3 scene;
    scene.extend(Vec3(-1.0));
    scene.extend(Vec3(1.0));
    const ViewSetup view = viewSetupFor(camera, scene);
    for (const Vec3 corner : {Vec3(-1, -1, -1), Vec3(1, 1, 1), Vec3(1, -1, 1), Vec3(-1, 1, -1)}) {
        const glm::dvec4 clip = glm::dmat4(view.projection) * glm::dmat4(view.view) * glm::dvec4(corner, 1.0);
        const double depth = clip.z / clip.w;
        EXPECT_GT(depth, -1.0);
        EXPECT_LT(depth, 1.0);
    }
}

const char* lookup(std::string_view name) {
    static const std::map<std::string, const char*, std::less<>> files = {
        {"a.glsl", "float a;\n#include \"b.glsl\"\n"},
        {"b.glsl", "float b;\n"},
        {"loop.glsl", "#include \"loop.glsl\"\nfloat once;\n"}};
    const auto it = files.find(name);
    return it == files.end() ? nullptr : it->second;
}

TEST(ShaderSource, DefinesFollowTheVersionAndIncludesAreInlinedOnce) {
    const std::string s =
        assembleShaderSource("x.frag", "#version 450 core\n#include \"a.glsl\"\n#include \"b.glsl\"\nvoid main() {}\n",
                             {"ONE", "TWO"}, lookup);
    EXPECT_EQ(s, "#version 450 core\n#define ONE\n#define TWO\nfloat a;\nfloat b;\nvoid main() {}\n");
    EXPECT_EQ(assembleShaderSource("l.frag", "#version 450 core\n#include \"loop.glsl\"\n", {}, lookup),
              "#version 450 core\nfloat once;\n");
}

TEST(ShaderSource, MissingFileAndMissingVersionAreErrorsNamingTheShader) {
    try {
        assembleShaderSource("x.frag", "#version 450 core\n#include \"nope.glsl\"\n", {}, lookup);
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_STREQ(e.what(), "x.frag: GLSL #include of unknown file 'nope.glsl'");
    }
    EXPECT_THROW(assembleShaderSource("y.frag", "void main() {}\n", {}, lookup), Error);
}

TEST(GpuLayout, StructsAreTheStd430Sizes) {
    // std430 lays out a struct of vec4s as consecutive 16-byte vec4s.
    EXPECT_EQ(sizeof(gpu::Light), 48u);
    EXPECT_EQ(offsetof(gpu::Light, spot), 32u);
    EXPECT_EQ(sizeof(gpu::Sample), 96u);
    EXPECT_EQ(sizeof(gpu::Received), 48u);
    EXPECT_EQ(offsetof(gpu::Sample, ball), 80u);
}

SampleSet threeSamples() {
    SampleSet s;
    s.positions = {{1, 2, 3}, {4, 5, 6}, {7, 8, 9}};
    s.radii = {0.1f, 0.2f, 0.3f};
    s.widths = {0.5f, 0.6f, 0.7f};
    s.weights = {1.0f, 2.0f, 0.5f};
    s.extinction = {{4, 4, 4}, {4, 4, 4}, {8, 8, 8}};
    s.region = {{0, 1}, {0, 1}, {1, 2}};
    s.image = {{-1, -2, -3}, {-4, -5, -6}, {-7, -8, -9}};
    s.boundary.resize(3);
    s.boundary[2] = BoundaryBall{{0, 0, 1}, 0.25f, 0.5f, 0.75f};
    s.parameters.regionAxis = 1;
    return s;
}

TEST(SamplePacking, EachFieldLandsWhereTheShaderReadsIt) {
    const std::vector<gpu::Sample> p = packSamples(threeSamples());
    ASSERT_EQ(p.size(), 3u);
    EXPECT_EQ(p[2].centreWidth, glm::vec4(7, 8, 9, 0.7f));
    EXPECT_EQ(p[2].scattering, glm::vec4(4, 4, 4, 0));  // weight times extinction: sigma_s per unit albedo
    EXPECT_EQ(p[2].extinction, glm::vec4(8, 8, 8, 0));
    EXPECT_EQ(p[2].region, glm::vec4(1, 2, 0.5f, 0.75f));  // slab, then the ball's curvature and share
    EXPECT_EQ(p[2].image, glm::vec4(-7, -8, -9, 0));
    EXPECT_EQ(p[2].ball, glm::vec4(0, 0, 1, 0.25f));
}

TEST(SlabTable, ConstantSlabsSortedAndEveryOtherCaseEmpty) {
    SampleSet s = threeSamples();
    const SlabTable table = findSlabs(s);
    ASSERT_EQ(table.bounds.size(), 2u);
    EXPECT_EQ(table.bounds[0], glm::vec4(0, 1, 0, 0));
    EXPECT_EQ(table.extinction[1], glm::vec4(8, 8, 8, 0));
    EXPECT_FALSE(isHomogeneous(s));

    SampleSet varying = s;  // sigma_t varies inside slab [0, 1]
    varying.extinction[1] = glm::vec3(5.0f);
    EXPECT_TRUE(findSlabs(varying).empty());
    SampleSet noAxis = s;
    noAxis.parameters.regionAxis = kNoRegionAxis;
    EXPECT_TRUE(findSlabs(noAxis).empty());
    SampleSet homogeneous = s;
    homogeneous.extinction[2] = glm::vec3(4.0f);
    EXPECT_TRUE(isHomogeneous(homogeneous));
    EXPECT_TRUE(findSlabs(homogeneous).empty());
    SampleSet many;  // one more slab than the shader's table holds
    for (size_t i = 0; i <= SlabTable::kMaxSlabs; ++i) {
        many.positions.emplace_back(0.0f);
        many.extinction.emplace_back(float(i + 1));
        many.region.emplace_back(float(i), float(i + 1));
    }
    many.parameters.regionAxis = 0;
    EXPECT_TRUE(findSlabs(many).empty());
}

TEST(BlockerShadowViews, ResolutionKeepsManyLightsWithinTheBudget) {
    EXPECT_EQ(blockerShadowResolution(1), 512);
    EXPECT_EQ(blockerShadowResolution(4), 512);
    for (size_t lights : {5u, 16u, 64u, 256u}) {
        const double bytes = 6.0 * double(lights) * std::pow(blockerShadowResolution(lights), 2) * 4.0;
        EXPECT_LE(bytes, 26.0e6) << lights;  // 4 lights at 512^2: 25.2 MB
    }
    EXPECT_EQ(blockerShadowResolution(1000), 64);  // the floor, past 256 lights
    EXPECT_EQ(blockerShadowLayers(0), 6);
    EXPECT_EQ(blockerShadowLayers(3), 18);
}

TEST(BlockerShadowViews, LayersKnowTheirLightAndAPlacedBoxHoldsItsCorners) {
    Light point;
    point.position = Vec3(1.0, 2.0, 3.0);
    Light directional;
    directional.type = Light::Type::Directional;
    directional.direction = Vec3(0.0, 0.0, -2.0);
    const std::vector<Light> lights{point, directional};
    for (int layer = 0; layer < 6; ++layer) EXPECT_EQ(layerLight(lights, layer), &lights[0]) << layer;
    EXPECT_EQ(layerLight(lights, 6), &lights[1]);
    for (int layer = 7; layer < 13; ++layer) EXPECT_EQ(layerLight(lights, layer), nullptr) << layer;
    EXPECT_EQ(packedLight(point), glm::vec4(1.0f, 2.0f, 3.0f, 1.0f));
    EXPECT_EQ(packedLight(directional), glm::vec4(0.0f, 0.0f, -1.0f, 0.0f));

    Bounds3 box;
    box.extend(Vec3(-1.0));
    box.extend(Vec3(1.0));
    Similarity eighthTurn;  // 45 degrees about z, doubled, moved along x
    eighthTurn.scale = 2.0;
    eighthTurn.rotation = glm::dmat3(glm::dvec3(0.70710678, 0.70710678, 0.0), glm::dvec3(-0.70710678, 0.70710678, 0.0),
                                     glm::dvec3(0.0, 0.0, 1.0));
    eighthTurn.translation = Vec3(5.0, 0.0, 0.0);
    const Bounds3 placed = placedBox(box, eighthTurn);
    const double reach = 2.0 * std::sqrt(2.0);  // a corner's distance from the axis, doubled
    EXPECT_NEAR(placed.min.x, 5.0 - reach, 1e-6);
    EXPECT_NEAR(placed.max.x, 5.0 + reach, 1e-6);
    EXPECT_NEAR(placed.max.y, reach, 1e-6);
    EXPECT_NEAR(placed.min.z, -2.0, 1e-12);
    EXPECT_NEAR(placed.max.z, 2.0, 1e-12);
}

TEST(BlockerShadowViews, EntryMapsKeepManyLightsWithinOneLightsBudget) {
    EXPECT_EQ(entryMapResolution(1), 512);
    for (size_t lights : {2u, 4u, 16u, 64u, 256u}) {
        const double bytes = 6.0 * double(lights) * std::pow(entryMapResolution(lights), 2) * 24.0;
        EXPECT_LE(bytes, 6.0 * 512 * 512 * 24.0) << lights;  // 37.7 MB
        EXPECT_GE(entryMapResolution(lights), 32);
    }
}

TEST(BlockerShadowViews, EachFaceSeesItsAxisAndTheDirectionalViewEnclosesTheBlockers) {
    Bounds3 blockers;
    blockers.extend(Vec3(-0.5));
    blockers.extend(Vec3(0.5));
    Light point;
    point.position = Vec3(3.0, 0.0, 0.0);
    Light directional;
    directional.type = Light::Type::Directional;
    directional.direction = Vec3(0.0, -1.0, 0.0);
    const std::vector<glm::mat4> views = blockerShadowViews({point, directional}, blockers);
    ASSERT_EQ(views.size(), 12u);
    for (int face = 0; face < 6; ++face) {
        // A point one unit from the light along the face's axis lands at the face's centre.
        glm::vec3 axis(0.0f);
        axis[face / 2] = face % 2 ? -1.0f : 1.0f;
        const glm::vec4 clip = views[size_t(face)] * glm::vec4(glm::vec3(point.position) + axis, 1.0f);
        EXPECT_NEAR(clip.x / clip.w, 0.0, 1e-5) << face;
        EXPECT_NEAR(clip.y / clip.w, 0.0, 1e-5) << face;
        EXPECT_GT(clip.z / clip.w, -1.0f);
    }
    for (const glm::vec3 corner : {glm::vec3(-0.5f), glm::vec3(0.5f), glm::vec3(0.5f, -0.5f, 0.5f)}) {
        const glm::vec4 clip = views[6] * glm::vec4(corner, 1.0f);
        for (int k = 0; k < 3; ++k) EXPECT_LE(std::abs(clip[k] / clip.w), 1.0f) << k;
    }
    EXPECT_EQ(views[7], glm::mat4(1.0f));  // a directional light uses one layer
}

// The default reduction of the scattering follows the samples' radius on screen:
// a reduced pixel at most 0.75 of it (docs/runtime.md has the measurements).
TEST(ScatterScale, FollowsTheSamplesRadiusOnScreen) {
    EXPECT_EQ(scatterScaleFor(1.4), 1);  // CGAL's elephant at 256x256
    EXPECT_EQ(scatterScaleFor(2.66), 1);
    EXPECT_EQ(scatterScaleFor(2.67), 2);
    EXPECT_EQ(scatterScaleFor(5.3), 2);
    EXPECT_EQ(scatterScaleFor(5.34), 4);
    EXPECT_EQ(scatterScaleFor(8.3), 4);  // the bunny at 800x800
    EXPECT_EQ(scatterScaleFor(kInfinity), 4);
    EXPECT_EQ(scatterScaleFor(0.0), 1);
    EXPECT_EQ(scatterScaleFor(std::nan("")), 1);
}

}  // namespace
}  // namespace lucent
