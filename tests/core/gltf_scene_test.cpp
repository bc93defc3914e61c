// glTF 2.0 scenes (core/gltf_scene.h): files written here, byte by byte, against
// the Lucent scene file that says the same thing, and hostile files.
#include "core/gltf_scene.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>

#include "core/error.h"
#include "core/volume_object.h"
#include "reference/reference_renderer.h"
#include "tests/support/test_support.h"

namespace lucent {
namespace {

using nlohmann::json;
using test::errorOf;

// A glTF asset built in memory: JSON plus one binary buffer.
struct GltfAsset {
    json gltf = {{"asset", {{"version", "2.0"}}}};
    std::string bin;

    int addAccessor(const void* data, size_t bytes, int componentType, const char* type, size_t count) {
        while (bin.size() % 4) bin.push_back('\0');
        json view = {{"buffer", 0}, {"byteOffset", bin.size()}, {"byteLength", bytes}};
        bin.append(static_cast<const char*>(data), bytes);
        gltf["bufferViews"].push_back(view);
        gltf["accessors"].push_back({{"bufferView", gltf["bufferViews"].size() - 1},
                                     {"componentType", componentType},
                                     {"type", type},
                                     {"count", count}});
        return int(gltf["accessors"].size() - 1);
    }
    // A mesh of triangles, every corner its own vertex (as an exporter splits
    // vertices whose normals differ), with indices; returns its index.
    int addSplitMesh(const TriangleMesh& m, int material) {
        std::vector<float> positions;
        std::vector<uint16_t> indices;
        for (const auto& t : m.triangles)
            for (uint32_t v : t) {
                for (int i = 0; i < 3; ++i) positions.push_back(float(m.positions[v][i]));
                indices.push_back(uint16_t(indices.size()));
            }
        const int p = addAccessor(positions.data(), positions.size() * 4, 5126, "VEC3", indices.size());
        const int i = addAccessor(indices.data(), indices.size() * 2, 5123, "SCALAR", indices.size());
        json primitive = {{"attributes", {{"POSITION", p}}}, {"indices", i}};
        if (material >= 0) primitive["material"] = material;
        gltf["meshes"].push_back({{"primitives", json::array({primitive})}});
        return int(gltf["meshes"].size() - 1);
    }
    int addNode(json node) {
        gltf["nodes"].push_back(std::move(node));
        const int index = int(gltf["nodes"].size() - 1);
        gltf["scenes"][0]["nodes"].push_back(index);
        return index;
    }
    std::filesystem::path writeGltf(const test::ScratchDir& dir, const std::string& name) {
        json g = gltf;
        if (!g.contains("buffers")) g["buffers"] = json::array({{{"uri", name + ".bin"}, {"byteLength", bin.size()}}});
        dir.write(name + ".bin", bin);
        return dir.write(name + ".gltf", g.dump());
    }
    std::filesystem::path writeGlb(const test::ScratchDir& dir, const std::string& name) {
        json g = gltf;
        if (!g.contains("buffers")) g["buffers"] = json::array({{{"byteLength", bin.size()}}});
        std::string text = g.dump();
        while (text.size() % 4) text.push_back(' ');
        std::string body = bin;
        while (body.size() % 4) body.push_back('\0');
        std::string out = "glTF";
        const auto u32 = [&](uint32_t v) { out.append(reinterpret_cast<const char*>(&v), 4); };
        u32(2);
        u32(uint32_t(12 + 8 + text.size() + 8 + body.size()));
        u32(uint32_t(text.size()));
        u32(0x4E4F534Au);
        out += text;
        u32(uint32_t(body.size()));
        u32(0x004E4942u);
        out += body;
        return dir.write(name + ".glb", out);
    }
};

// KHR_materials_volume_scatter's published forward map (OpenPBR): the
// multiple-scattering albedo of a single-scattering albedo a and anisotropy g.
double multiscatterOf(double a, double g) {
    const double s = std::sqrt((1.0 - a) / (1.0 - g * a));
    return (1.0 - s) * (1.0 - 0.139 * s) / (1.0 + 1.17 * s);
}

// The single-scattering albedo giving multiscatter, by bisection on the forward map.
double albedoByBisection(double multiscatter, double g) {
    double lo = 0.0, hi = 1.0;
    for (int i = 0; i < 100; ++i) {
        const double mid = 0.5 * (lo + hi);
        (multiscatterOf(mid, g) < multiscatter ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

TEST(GltfScene, TheAlbedoMappingInvertsThePublishedMultipleScatteringAlbedo) {
    for (double g : {-0.6, 0.0, 0.3, 0.9})
        for (double a : {0.0, 0.1, 0.5, 0.8, 0.95, 0.999, 1.0}) {
            const double ms = a < 1.0 ? multiscatterOf(a, g) : 1.0;
            EXPECT_NEAR(singleScatteringAlbedo(ms, g), a, 1e-9) << "a " << a << " g " << g;
        }
    EXPECT_EQ(singleScatteringAlbedo(-1.0, 0.0), 0.0);  // out of range: clamped, never NaN
    EXPECT_EQ(singleScatteringAlbedo(2.0, 0.0), 1.0);
}

// The wax box: a glTF of every feature that maps, and the Lucent scene file
// that says the same in Lucent's words, each number converted by hand here.
struct WaxBox {
    test::ScratchDir dir;
    GltfAsset asset;
    std::filesystem::path obj;
    const Rgb attenuationColor{0.2, 0.4, 0.6};
    const double attenuationDistance = 0.5;
    const Rgb multiscatter{0.9, 0.7, 0.5};
    const double g = 0.3, ior = 1.4;

    WaxBox() {
        obj = test::writeBox(dir, "box.obj", Vec3(-0.5, -0.4, -0.3), Vec3(0.5, 0.4, 0.3));
        std::vector<std::string> warnings;
        const TriangleMesh box = loadClosedMesh(obj, warnings);
        asset.gltf["extensionsUsed"] = {"KHR_materials_volume", "KHR_materials_volume_scatter", "KHR_materials_ior",
                                        "KHR_lights_punctual"};
        asset.gltf["materials"].push_back(
            {{"name", "wax"},
             {"extensions",
              {{"KHR_materials_volume",
                {{"attenuationColor", {attenuationColor.r, attenuationColor.g, attenuationColor.b}},
                 {"attenuationDistance", attenuationDistance}}},
               {"KHR_materials_volume_scatter",
                {{"multiscatterColor", {multiscatter.r, multiscatter.g, multiscatter.b}}, {"scatterAnisotropy", g}}},
               {"KHR_materials_ior", {{"ior", ior}}}}}});
        const int mesh = asset.addSplitMesh(box, 0);
        // Rotated 30 degrees about (1, 1, 0), scaled 0.8, moved: a similarity.
        const glm::dquat q = glm::angleAxis(glm::radians(30.0), glm::normalize(Vec3(1, 1, 0)));
        asset.addNode({{"name", "Wax Box"},
                       {"mesh", mesh},
                       {"rotation", {q.x, q.y, q.z, q.w}},
                       {"scale", {0.8, 0.8, 0.8}},
                       {"translation", {0.1, -0.2, 0.3}}});
        asset.gltf["extensions"]["KHR_lights_punctual"]["lights"] = {
            {{"type", "point"}, {"color", {1.0, 0.8, 0.6}}, {"intensity", 683.0 * 3.0}},
            {{"type", "spot"},
             {"intensity", 683.0 * 2.0},
             {"spot", {{"innerConeAngle", 0.2}, {"outerConeAngle", 0.5}}}}};
        asset.addNode({{"translation", {1.5, 2.0, 2.5}}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
        // The spot stands on -x and points along +x: -z turned by +90 degrees about y.
        const glm::dquat spot = glm::angleAxis(glm::radians(-90.0), Vec3(0, 1, 0));
        asset.addNode({{"translation", {-3.0, 0.2, 0.0}},
                       {"rotation", {spot.x, spot.y, spot.z, spot.w}},
                       {"extensions", {{"KHR_lights_punctual", {{"light", 1}}}}}});
        asset.gltf["cameras"].push_back(
            {{"name", "front"}, {"type", "perspective"}, {"perspective", {{"yfov", 0.6}, {"znear", 0.01}}}});
        asset.addNode({{"name", "Camera"}, {"camera", 0}, {"translation", {0.4, 0.3, 4.0}}});
    }

    // The same scene in Lucent's words.
    std::filesystem::path sceneFile() const {
        char text[4096];
        const Rgb sigmaT = -glm::log(attenuationColor) / attenuationDistance;  // KHR_materials_volume
        Rgb albedo;
        for (int i = 0; i < 3; ++i) albedo[i] = albedoByBisection(multiscatter[i], g);
        std::snprintf(text, sizeof text,
                      R"({"units": "m",
  "camera": {"position": [0.4, 0.3, 4.0], "target": [0.4, 0.3, 3.0], "fov_y": %.17g, "width": 512, "height": 512},
  "lights": [{"type": "point", "position": [1.5, 2.0, 2.5], "intensity": [3.0, 2.4, 1.8]},
             {"type": "spot", "position": [-3.0, 0.2, 0.0], "direction": [1, 0, 0], "intensity": 2.0,
              "inner_angle": %.17g, "outer_angle": %.17g}],
  "objects": [{"mesh": "box.obj",
               "medium": {"sigma_t": [%.17g, %.17g, %.17g], "albedo": [%.17g, %.17g, %.17g], "g": %.17g, "ior": %.17g},
               "transform": {"scale": 0.8, "rotate": {"axis": [1, 1, 0], "degrees": 30}, "translate": [0.1, -0.2, 0.3]},
               "samples": "box.lsf"}]})",
                      glm::degrees(0.6), glm::degrees(0.2), glm::degrees(0.5), sigmaT.r, sigmaT.g, sigmaT.b, albedo.r,
                      albedo.g, albedo.b, g, ior);
        return dir.write("box.json", text);
    }
};

Image referenceImage(SceneDesc scene) {
    scene.camera.width = scene.camera.height = 20;
    std::vector<std::string> warnings;
    const std::vector<VolumeObject> objects = loadObjects(scene, warnings);
    ReferenceSettings settings;
    settings.tolerance = 1e-4;
    return ReferenceRenderer(scene, objects).render(settings);
}

double largestRelativeDifference(const Image& a, const Image& b) {
    double peak = 0.0, worst = 0.0;
    for (size_t i = 0; i < a.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            peak = std::max(peak, double(b.pixels[i][c]));
            worst = std::max(worst, double(std::abs(a.pixels[i][c] - b.pixels[i][c])));
        }
    return peak > 0.0 ? worst / peak : 1.0;
}

TEST(GltfScene, AGltfSceneRendersAsTheSceneFileThatSaysTheSame) {
    WaxBox box;
    const SceneDesc imported = parseScene(box.asset.writeGltf(box.dir, "wax"));
    const SceneDesc written = parseScene(box.sceneFile());
    ASSERT_EQ(imported.objects.size(), 1u);
    EXPECT_EQ(imported.objects[0].name, "Wax Box");
    EXPECT_EQ(imported.objects[0].samples,
              box.dir.path() / "wax.Wax_Box.lsf");  // beside the model, named after the node
    EXPECT_EQ(imported.lights.size(), 2u);
    EXPECT_TRUE(imported.warnings.empty()) << imported.warnings.front();
    const Image a = referenceImage(imported), b = referenceImage(written);
    ASSERT_EQ(a.pixels.size(), b.pixels.size());
    double peak = 0.0;
    for (const auto& p : b.pixels) peak = std::max(peak, double(p.r));
    ASSERT_GT(peak, 0.0) << "the scene is lit";
    EXPECT_LT(largestRelativeDifference(a, b), 1e-6);
    // .glb holds the same scene in one file.
    const Image c = referenceImage(parseScene(box.asset.writeGlb(box.dir, "wax")));
    EXPECT_LT(largestRelativeDifference(c, b), 1e-6);
}

TEST(GltfScene, ExporterSeamsAreWeldedIntoAClosedMesh) {
    WaxBox box;
    const SceneDesc scene = parseScene(box.asset.writeGlb(box.dir, "wax"));
    std::vector<std::string> warnings;
    const TriangleMesh mesh = loadGltfMesh(scene.objects[0].mesh, scene.objects[0].gltfNode, warnings);
    EXPECT_EQ(mesh.positions.size(), 8u);  // 36 split corners, 8 places
    EXPECT_EQ(mesh.triangles.size(), 12u);
    EXPECT_NEAR(mesh.signedVolume(), 1.0 * 0.8 * 0.6, 1e-6);
}

TEST(GltfScene, AMatrixThatIsNoSimilarityIsBakedIntoTheMeshWithANote) {
    WaxBox box;
    box.asset.gltf["nodes"][0].erase("rotation");
    box.asset.gltf["nodes"][0]["scale"] = {1.0, 2.0, 0.5};
    const SceneDesc scene = parseScene(box.asset.writeGltf(box.dir, "wax"));
    EXPECT_TRUE(scene.objects[0].transform.isIdentity());
    ASSERT_EQ(scene.warnings.size(), 1u);
    EXPECT_CONTAINS(scene.warnings[0], "baked into the mesh");
    std::vector<std::string> warnings;
    const Bounds3 b = loadGltfMesh(scene.objects[0].mesh, scene.objects[0].gltfNode, warnings).bounds();
    EXPECT_NEAR(b.max.x, 0.1 + 0.5, 1e-6);
    EXPECT_NEAR(b.max.y, -0.2 + 0.8, 1e-6);
    EXPECT_NEAR(b.max.z, 0.3 + 0.15, 1e-6);
}

TEST(GltfScene, UnmappedFeaturesAndOpaqueNodesAreOneWarningEach) {
    WaxBox box;
    box.asset.gltf["materials"].push_back({{"name", "paint"}, {"emissiveFactor", {1, 0, 0}}});
    std::vector<std::string> warnings;
    const int opaque = box.asset.addSplitMesh(loadClosedMesh(box.obj, warnings), 1);
    box.asset.addNode({{"name", "Plinth"}, {"mesh", opaque}});
    box.asset.gltf["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", 0}};
    const SceneDesc scene = parseScene(box.asset.writeGltf(box.dir, "wax"));
    EXPECT_EQ(scene.objects.size(), 1u);
    std::string all;
    for (const auto& w : scene.warnings) all += w + "\n";
    EXPECT_CONTAINS(all, "node 'Plinth' has no KHR_materials_volume: it is opaque and left out");
    EXPECT_CONTAINS(all, "textures are not mapped");
    EXPECT_CONTAINS(all, "emission are not mapped");
    EXPECT_EQ(scene.warnings.size(), 3u) << all;
}

TEST(GltfScene, AVolumeThatOnlyAbsorbsIsSaidToDrawBlack) {
    WaxBox box;
    box.asset.gltf["materials"][0]["extensions"].erase("KHR_materials_volume_scatter");
    const SceneDesc scene = parseScene(box.asset.writeGltf(box.dir, "wax"));
    EXPECT_EQ(scene.objects[0].medium.albedo, Rgb(0.0));
    ASSERT_EQ(scene.warnings.size(), 1u);
    EXPECT_CONTAINS(scene.warnings[0], "absorbs and does not scatter (coloured glass)");
    EXPECT_CONTAINS(scene.warnings[0], "every method draws it black");
}

TEST(GltfScene, TheCameraIsChosenByNameOrFramesTheObjects) {
    WaxBox box;
    const auto file = box.asset.writeGltf(box.dir, "wax");
    EXPECT_EQ(parseScene(file, "front").camera.position, Vec3(0.4, 0.3, 4.0));
    EXPECT_CONTAINS(errorOf([&] { parseScene(file, "side"); }), "has no camera named 'side' (cameras: 'Camera')");
    box.asset.gltf["nodes"][3].erase("camera");
    const Camera framing = parseScene(box.asset.writeGltf(box.dir, "nocamera")).camera;
    EXPECT_GT(framing.position.z, 1.0);  // on +z, outside the box, looking at its centre
    EXPECT_LT(glm::length(framing.target - Vec3(0.1, -0.2, 0.3)), 0.5);
}

// A file as Blender 3.4.1's own exporter writes it (tests/data/gltf/, with the
// script that made it): split vertices, z-up turned y-up, watts turned candela
// and lux, a volume that absorbs only. The expected values are Blender's
// settings converted by hand: (x, y, z) in Blender is (x, z, -y) in glTF.
TEST(GltfScene, ABlenderExportMapsAsItsSettingsSay) {
    const auto file = test::sourceDir() / "tests/data/gltf/blender-cube.glb";
    const SceneDesc scene = parseScene(file);
    ASSERT_EQ(scene.objects.size(), 1u);
    const ObjectDesc& jade = scene.objects[0];
    EXPECT_EQ(jade.name, "Jade");
    EXPECT_NEAR(jade.medium.ior, 1.45, 1e-6);
    // Volume Absorption colour (0.3, 0.7, 0.5), density 2: attenuationDistance 1/2.
    EXPECT_NEAR(jade.medium.sigmaT.r, -std::log(0.3) * 2.0, 1e-6);
    EXPECT_NEAR(jade.medium.sigmaT.g, -std::log(0.7) * 2.0, 1e-6);
    EXPECT_EQ(jade.medium.albedo, Rgb(0.0));
    // Rotated 25 degrees about Blender's z (glTF's y), at Blender (0.2, -0.1, 0.3).
    EXPECT_NEAR(jade.transform.scale, 1.0, 1e-6);
    EXPECT_NEAR(glm::length(jade.transform.translation - Vec3(0.2, 0.3, 0.1)), 0.0, 1e-6);
    EXPECT_NEAR(glm::length(jade.transform.direction(Vec3(1, 0, 0)) -
                            Vec3(std::cos(glm::radians(25.0)), 0.0, -std::sin(glm::radians(25.0)))),
                0.0, 1e-6);
    // A 1000 W point light is 1000 / (4 pi) W/sr; a 3 W/m^2 sun stays 3 W/m^2.
    ASSERT_EQ(scene.lights.size(), 2u);
    EXPECT_NEAR(scene.lights[0].power.r, 1000.0 / (4.0 * M_PI), 1e-3);
    EXPECT_NEAR(glm::length(scene.lights[0].position - Vec3(3.0, 4.0, 2.0)), 0.0, 1e-6);
    EXPECT_EQ(scene.lights[1].type, Light::Type::Directional);
    EXPECT_NEAR(scene.lights[1].power.g, 3.0, 1e-9);
    // The sun turned 30 degrees about x shines along (0, sin 30, -cos 30) in Blender.
    EXPECT_NEAR(glm::length(scene.lights[1].direction - Vec3(0.0, -std::cos(glm::radians(30.0)), -0.5)), 0.0, 1e-6);
    // The camera at Blender (0, -8, 2), turned 80 degrees about x; its yfov as
    // the file holds it (Blender fits its sensor to the width: 50.6 degrees).
    EXPECT_NEAR(scene.camera.fovYDegrees, glm::degrees(0.8835458755493164), 1e-9);
    EXPECT_NEAR(glm::length(scene.camera.position - Vec3(0.0, 2.0, 8.0)), 0.0, 1e-6);
    const Vec3 forward = glm::normalize(scene.camera.target - scene.camera.position);
    EXPECT_NEAR(glm::length(forward - Vec3(0.0, -std::cos(glm::radians(80.0)), -std::sin(glm::radians(80.0)))), 0.0,
                1e-6);

    // The same scene written by hand renders the same. The medium only absorbs,
    // so single scattering would be black in both: both are given albedo 0.8.
    test::ScratchDir dir;
    const double e = 0.9999998807907104;  // the corners as Blender wrote them (single precision)
    test::writeBox(dir, "cube.obj", Vec3(-e, -1.0, -e), Vec3(e, 1.0, e));
    char text[2048];
    std::snprintf(
        text, sizeof text,
        R"({"camera": {"position": [0, 2, 8], "target": [0, %.17g, %.17g], "fov_y": %.17g, "width": 8, "height": 8},
  "lights": [{"type": "point", "position": [3, 4, 2], "intensity": %.17g},
             {"type": "directional", "direction": [0, %.17g, -0.5], "irradiance": 3}],
  "objects": [{"mesh": "cube.obj", "medium": {"sigma_t": [%.17g, %.17g, %.17g], "albedo": 0.8, "ior": %.17g},
               "transform": {"rotate": {"axis": [0, 1, 0], "degrees": 25}, "translate": [0.2, 0.3, 0.1]},
               "samples": "cube.lsf"}]})",
        2.0 - std::cos(glm::radians(80.0)), 8.0 - std::sin(glm::radians(80.0)), glm::degrees(0.8835458755493164),
        1000.0 / (4.0 * M_PI), -std::cos(glm::radians(30.0)), -std::log(0.3) * 2.0, -std::log(0.7) * 2.0,
        -std::log(0.5) * 2.0, 1.45);
    SceneDesc imported = scene, written = parseScene(dir.write("cube.json", text));
    imported.objects[0].medium.albedo = Rgb(0.8);
    const Image a = referenceImage(imported), b = referenceImage(written);
    EXPECT_LT(largestRelativeDifference(a, b), 1e-6);
}

// Hostile files: one clear line each, never a read outside the model's folder.
std::string importErrorOf(GltfAsset asset, const std::function<void(json&)>& edit, bool binary = false) {
    test::ScratchDir dir;
    edit(asset.gltf);
    const auto file = binary ? asset.writeGlb(dir, "m") : asset.writeGltf(dir, "m");
    return errorOf([&] {
        const SceneDesc scene = parseScene(file);
        std::vector<std::string> warnings;
        loadObjects(scene, warnings);
    });
}

TEST(GltfScene, HostileFilesGetOneErrorLine) {
    WaxBox box;
    const auto withBuffer = [&](const std::string& uri) {
        return importErrorOf(box.asset, [&](json& g) {
            g["buffers"] = json::array({{{"uri", uri}, {"byteLength", 4}}});
        });
    };
    EXPECT_CONTAINS(withBuffer("../outside.bin"), "leaves the model's folder");
    EXPECT_CONTAINS(withBuffer("/etc/passwd"), "is an absolute path");
    EXPECT_CONTAINS(withBuffer("file:///etc/passwd"), "has a scheme");
    EXPECT_CONTAINS(withBuffer("missing.bin"), "m.gltf: ");
    EXPECT_CONTAINS(importErrorOf(box.asset, [](json& g) { g["accessors"][0]["count"] = 100000; }),
                    "elements run past the end of its buffer view");
    EXPECT_CONTAINS(importErrorOf(box.asset, [](json& g) { g["bufferViews"][1]["byteOffset"] = 1u << 30; }),
                    "runs past the end of its buffer");
    EXPECT_CONTAINS(importErrorOf(box.asset, [](json& g) { g["accessors"][1]["componentType"] = 5126; }),
                    "indices must be unsigned integer SCALARs");
    EXPECT_CONTAINS(importErrorOf(box.asset, [](json& g) { g["nodes"][0]["children"] = {0}; }), "reached twice");
    // Found by lucent-fuzz-gltf: a node naming a mesh that does not exist.
    EXPECT_CONTAINS(importErrorOf(box.asset, [](json& g) { g["nodes"][0]["mesh"] = 7; }), "refers to mesh 7 of 1");
    EXPECT_CONTAINS(importErrorOf(box.asset,
                                  [](json& g) {
                                      g["nodes"][0]["translation"] = {1e300, 0, 0};
                                  }),
                    "not finite");
    EXPECT_CONTAINS(
        importErrorOf(box.asset,
                      [](json& g) {
                          g["materials"][0]["extensions"] = {{"KHR_materials_transmission", json::object()}};
                      }),
        "thin surface with no interior");
    EXPECT_CONTAINS(importErrorOf(box.asset, [](json& g) { g["materials"][0].erase("extensions"); }),
                    "nothing translucent to render");
    EXPECT_CONTAINS(
        importErrorOf(box.asset, [](json& g) { g["materials"][0]["extensions"]["KHR_materials_ior"]["ior"] = 0.5; }),
        "outside the [1, 4] Lucent renders");
    EXPECT_CONTAINS(importErrorOf(
                        box.asset,
                        [](json& g) {
                            g["buffers"] = json::array({{{"byteLength", 1e15}}});
                        },
                        true),
                    "memory budget");
    // Seams left open (one triangle gone): refused by the closed-mesh check, naming the node.
    EXPECT_CONTAINS(importErrorOf(box.asset, [](json& g) { g["accessors"][1]["count"] = 33; }), "node 'Wax Box'");
}

TEST(GltfScene, BrokenBinaryContainersAreRefused) {
    WaxBox box;
    const auto glb = box.asset.writeGlb(box.dir, "wax");
    std::ifstream in(glb, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_CONTAINS(errorOf([&] { parseScene(box.dir.write("cut.glb", bytes.substr(0, bytes.size() - 8))); }),
                    "header says");
    std::string bigChunk = bytes;
    const uint32_t huge = 0x7fffffff;
    std::memcpy(&bigChunk[12], &huge, 4);
    EXPECT_CONTAINS(errorOf([&] { parseScene(box.dir.write("chunk.glb", bigChunk)); }), "JSON chunk inside the file");
    EXPECT_CONTAINS(errorOf([&] { parseScene(box.dir.write("text.glb", "not a glb at all, not at all")); }),
                    "not a binary glTF file");
    // Only regular files, as for every input.
    const auto fifo = box.dir.path() / "fifo.glb";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    EXPECT_CONTAINS(errorOf([&] { parseScene(fifo); }), "it is a FIFO, not a regular file");
}

TEST(GltfScene, ABufferLinkedFromOutsideTheFolderIsNotRead) {
    test::ScratchDir outside, dir;
    WaxBox box;
    const auto secret = outside.write("secret.bin", box.asset.bin);
    std::filesystem::create_symlink(secret, dir.path() / "m.bin");
    json g = box.asset.gltf;
    g["buffers"] = json::array({{{"uri", "m.bin"}, {"byteLength", box.asset.bin.size()}}});
    const auto file = dir.write("m.gltf", g.dump());
    EXPECT_CONTAINS(errorOf([&] { parseScene(file); }), "outside the model's folder");
}

}  // namespace
}  // namespace lucent
