// Objects placed by a scene's "transform" (uniform scale, rotation, translation):
// the world the transport methods see must be that of the mesh moved there, so
// each check compares a placed object with the same mesh whose vertices were
// moved beforehand by glm's own matrices (glm::rotate, not core/similarity.cpp)
// and written to a file. Every method but ss (the reference, the path tracer,
// LBL, MDOM) reads objects through VolumeObject: these checks hold for all.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cstdio>
#include <fstream>

#include "core/error.h"
#include "core/image_compare.h"
#include "core/rng.h"
#include "core/scene.h"
#include "core/volume_object.h"
#include "preprocess/preprocessor.h"
#include "reference/reference_renderer.h"
#include "tests/support/test_support.h"

namespace lucent {
namespace {

const double kScale = 1.7, kDegrees = 37.0;
const Vec3 kAxis(1.0, 2.0, 3.0), kTranslate(0.4, -0.3, 0.25);

glm::dmat4 glmPlacement() {
    return glm::translate(glm::dmat4(1.0), kTranslate) *
           glm::rotate(glm::dmat4(1.0), glm::radians(kDegrees), glm::normalize(kAxis)) *
           glm::scale(glm::dmat4(1.0), Vec3(kScale));
}

// mesh's vertices multiplied by m, as an OBJ in dir.
std::filesystem::path writeMoved(const test::ScratchDir& dir, const std::string& name,
                                 const std::filesystem::path& mesh, const glm::dmat4& m) {
    std::vector<std::string> warnings;
    const TriangleMesh loaded = loadClosedMesh(mesh, warnings);
    std::string obj;
    char line[160];
    for (const Vec3& p : loaded.positions) {
        const glm::dvec4 q = m * glm::dvec4(p, 1.0);
        std::snprintf(line, sizeof line, "v %.17g %.17g %.17g\n", q.x, q.y, q.z);
        obj += line;
    }
    for (const auto& t : loaded.triangles)
        obj += "f " + std::to_string(t[0] + 1) + " " + std::to_string(t[1] + 1) + " " + std::to_string(t[2] + 1) + "\n";
    return dir.write(name, obj);
}

TEST(Placement, TheScenesTransformIsScaleThenRotationThenTranslation) {
    const SceneDesc s = parseSceneText(R"({
      "camera": {"position": [0, 0, 5], "target": [0, 0, 0], "fov_y": 40, "width": 8, "height": 8}, "lights": [],
      "objects": [{"mesh": "m.obj", "medium": {"sigma_t": 1, "albedo": 0.5}, "samples": "s.lsf",
                   "transform": {"scale": 2, "rotate": {"axis": [0, 0, 5], "degrees": 90}, "translate": [1, 2, 3]}},
                  {"mesh": "m.obj", "medium": {"sigma_t": 1, "albedo": 0.5}, "samples": "t.lsf",
                   "transform": {"scale": [3, 3, 3]}}]})",
                                       "dir/scene.json");
    // 90 degrees about +z takes x to y: (1, 0, 0) -> scale 2 -> (0, 2, 0) -> + (1, 2, 3).
    const Vec3 p = s.objects[0].transform.point(Vec3(1, 0, 0));
    EXPECT_NEAR(glm::length(p - Vec3(1, 4, 3)), 0.0, 1e-12);
    EXPECT_NEAR(glm::length(s.objects[0].transform.inversePoint(p) - Vec3(1, 0, 0)), 0.0, 1e-12);
    EXPECT_DOUBLE_EQ(s.objects[1].transform.scale, 3.0);
    // The transform is not the sample file's business: the same object placed
    // anywhere keeps its fingerprint.
    EXPECT_EQ(s.objects[0].fingerprint, s.objects[1].fingerprint);
}

TEST(Placement, BadTransformsAreOneLineErrors) {
    const std::string base =
        R"({"camera": {"position": [0, 0, 5], "target": [0, 0, 0], "fov_y": 40, "width": 8, "height": 8},
      "lights": [], "objects": [{"mesh": "m.obj", "medium": {"sigma_t": 1, "albedo": 0.5}, "samples": "s.lsf",
      "transform": T}]})";
    auto errorOf = [&](const std::string& transform) {
        std::string text = base;
        text.replace(text.find(" T}"), 2, " " + transform);
        return test::sceneErrorOf(text);
    };
    const std::pair<std::string, std::string> cases[] = {
        {R"({"scale": [1, 2, 1]})", "/objects/0/transform/scale: a non-uniform scale is not supported"},
        {R"({"scale": 0})", "/objects/0/transform/scale: must lie in [1e-09, 1e+09]"},
        {R"({"scale": -1})", "/objects/0/transform/scale: must lie in"},
        {R"({"rotate": {"axis": [0, 0, 0], "degrees": 10}})",
         "/objects/0/transform/rotate/axis: must not be the zero vector"},
        {R"({"rotate": {"axis": [0, 0, 1]}})", "/objects/0/transform/rotate: missing required key 'degrees'"},
        {R"({"translate": [0, 1e14, 0]})", "/objects/0/transform/translate/1: must lie in"},
        {R"({"shear": 1})", "/objects/0/transform/shear: unknown key"},
        {R"([1, 0, 0])", "/objects/0/transform: must be an object"},
    };
    for (const auto& [transform, message] : cases) {
        const std::string got = errorOf(transform);
        EXPECT_NE(got.find(message), std::string::npos) << transform << " gave: " << got;
        EXPECT_EQ(got.find('\n'), std::string::npos) << got;
    }
}

// Optical depths, membership and extinction of the placed object are those of
// the moved mesh, with the layers carried along: a layered cube turned by 90
// degrees about z has, in the world, the same layers along y.
TEST(Placement, APlacedObjectIsItsMovedMesh) {
    test::ScratchDir dir;
    const auto cube = test::writeBox(dir, "cube.obj", Vec3(-0.6, -0.5, -0.4), Vec3(0.6, 0.5, 0.4));
    struct Case {
        const char* name;
        std::filesystem::path mesh;
        glm::dmat4 moved;
        Similarity placement;
        DensityDesc placedDensity, movedDensity;
    };
    DensityDesc layersX, layersY;
    layersX.type = layersY.type = DensityDesc::Type::Layers;
    layersX.axis = 0;
    layersY.axis = 1;
    layersX.values = layersY.values = {0.5, 2.0, 1.0};
    const glm::dmat4 quarterTurn = glm::translate(glm::dmat4(1.0), kTranslate) *
                                   glm::rotate(glm::dmat4(1.0), glm::radians(90.0), Vec3(0, 0, 1)) *
                                   glm::scale(glm::dmat4(1.0), Vec3(kScale));
    const Case cases[] = {
        {"bunny",
         test::modelsDir() / "bunny.off",
         glmPlacement(),
         makeSimilarity(kScale, kAxis, kDegrees, kTranslate),
         {},
         {}},
        {"layered box", cube, quarterTurn, makeSimilarity(kScale, Vec3(0, 0, 1), 90.0, kTranslate), layersX, layersY},
    };
    for (const Case& c : cases) {
        ObjectDesc placed = test::simpleObject(c.mesh, 3.0);
        placed.transform = c.placement;
        placed.medium.density = c.placedDensity;
        ObjectDesc moved = test::simpleObject(writeMoved(dir, std::string(c.name) + ".obj", c.mesh, c.moved), 3.0);
        moved.medium.density = c.movedDensity;
        std::vector<std::string> warnings;
        const VolumeObject a(placed, warnings), b(moved, warnings);
        // Mesh files are read in single precision (and Embree casts in it): the
        // moved mesh's vertices are the placed ones rounded to floats.
        const Bounds3 box = b.mesh().bounds();
        const double tolerance = 1e-5 * box.diagonal();
        EXPECT_NEAR(glm::length(a.mesh().bounds().min - box.min), 0.0, tolerance) << c.name;
        Rng rng(7, 0);
        int inside = 0;
        for (int i = 0; i < 400; ++i) {
            const Vec3 p = box.min + Vec3(rng.uniform(), rng.uniform(), rng.uniform()) * box.extent();
            const Vec3 d = glm::normalize(Vec3(rng.uniform(), rng.uniform(), rng.uniform()) - 0.5);
            ASSERT_EQ(a.contains(p), b.contains(p)) << c.name << " at " << i;
            inside += a.contains(p);
            EXPECT_NEAR(a.extinction(p).r, b.extinction(p).r, 1e-9) << c.name;
            // Density at most 2 along at most the diagonal: a length error of tolerance.
            EXPECT_NEAR(a.densityPath(p, d), b.densityPath(p, d), 2.0 * tolerance) << c.name << " at " << i;
        }
        EXPECT_GT(inside, 40) << c.name;
    }
}

// The reference of a placed object is the reference of its moved mesh, surface
// term included (shading normals rotate with the object).
TEST(Placement, TheReferenceSeesThePlacedObject) {
    test::ScratchDir dir;
    SceneDesc placed;
    placed.camera.position = Vec3(0.5, 1.0, 6.0);
    placed.camera.target = kTranslate;
    placed.camera.width = placed.camera.height = 40;
    placed.lights = {test::pointLight(Vec3(3, 3, 2), Rgb(30.0))};
    ObjectDesc o = test::simpleObject(test::modelsDir() / "bunny.off", 4.0, 0.8);
    o.surface = SurfaceDesc{};
    o.transform = makeSimilarity(kScale, kAxis, kDegrees, kTranslate);
    placed.objects = {o};
    SceneDesc moved = placed;
    moved.objects[0].mesh = writeMoved(dir, "moved.obj", o.mesh, glmPlacement());
    moved.objects[0].transform = Similarity{};
    std::vector<std::string> warnings;
    const auto a = loadObjects(placed, warnings), b = loadObjects(moved, warnings);
    ReferenceSettings settings;
    settings.tolerance = 1e-4;
    const ImageError e =
        compareImages(ReferenceRenderer(placed, a).render(settings), ReferenceRenderer(moved, b).render(settings));
    EXPECT_GT(e.pixels, 100u);
    // Only the quadrature's own tolerance per pixel may set them apart.
    EXPECT_LT(e.relativeRmse, 10.0 * settings.tolerance);
}

// A placed object is sampled in its own space at its placement's scale: the
// samples of the sphere placed at 2 (sigma_t 1) are those of the sphere with
// sigma_t 2 in its own space, their coefficients per world unit; rotation and
// translation play no part.
TEST(Placement, PreprocessingSamplesAPlacedObjectAtItsScale) {
    ObjectDesc o = test::simpleObject(test::modelsDir() / "sphere.obj", 1.0);
    o.transform = makeSimilarity(2.0, Vec3(0, 0, 1), 40.0, Vec3(3.0, 0.0, 0.0));
    std::vector<std::string> warnings;
    const VolumeObject placed(o, warnings);
    EXPECT_TRUE(placed.placed());
    EXPECT_EQ(placed.objectMesh().bounds().max, loadClosedMesh(o.mesh, warnings).bounds().max);
    const SampleSet fromPlaced = preprocessObject(placed, qualityPreset("draft"));
    ObjectDesc denser = o;
    denser.transform = Similarity{};
    denser.medium.sigmaT = Rgb(2.0);
    const SampleSet own = preprocessObject(VolumeObject(denser, warnings), qualityPreset("draft"));
    EXPECT_EQ(fromPlaced.parameters.placementScale, 2.0f);
    EXPECT_EQ(own.parameters.placementScale, 1.0f);
    ASSERT_EQ(fromPlaced.size(), own.size());
    ASSERT_GT(own.size(), 100u);
    EXPECT_EQ(fromPlaced.positions, own.positions);
    EXPECT_EQ(fromPlaced.coefficients(), own.coefficients());
    for (size_t i = 0; i < own.size(); i += 97) {
        EXPECT_FLOAT_EQ(fromPlaced.extinction[i].g, 1.0f);
        EXPECT_FLOAT_EQ(fromPlaced.weights[i], own.weights[i]);  // sigma_s per world unit: half of own's
    }
    SceneDesc scene;
    scene.objects = {o};
    EXPECT_TRUE(withoutTransforms(scene).objects[0].transform.isIdentity());
}

TEST(Placement, AScaleThatLeavesTheSupportedCoordinatesIsAnError) {
    ObjectDesc o = test::simpleObject(test::modelsDir() / "sphere.obj", 1.0);
    o.transform = makeSimilarity(1e9, Vec3(0, 0, 1), 0.0, Vec3(0.0, 9.9999e12, 0.0));
    std::vector<std::string> warnings;
    try {
        VolumeObject placed(o, warnings);
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("beyond the 1e13 coordinates"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace lucent
