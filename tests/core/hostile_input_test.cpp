// Hostile input, class by class (docs/robustness.md), at the level of the
// readers: every test here fed its input to Lucent before these checks existed
// and got a hang, a memory bomb, a crash, a wrong image or an unclear error.
#include <gtest/gtest.h>
#include <openvdb/openvdb.h>
#include <sys/stat.h>

#include <fstream>

#include "core/density_field.h"
#include "core/error.h"
#include "core/input_file.h"
#include "core/limits.h"
#include "core/sample_set.h"
#include "core/scene.h"
#include "core/triangle_mesh.h"
#include "core/volume_object.h"
#include "reference/reference_renderer.h"
#include "tests/support/test_support.h"

namespace lucent {
namespace {

using test::errorOf;

std::string sceneWith(const std::string& camera, const std::string& light, const std::string& mesh,
                      const std::string& medium = R"("sigma_t": 2, "albedo": 0.5)") {
    return R"({"camera": {"position": )" + camera + R"(, "target": [0, 0, 0], "fov_y": 40, "width": 8, "height": 8},
               "lights": [)" +
           light + R"(], "objects": [{"mesh": ")" + mesh + R"(", "medium": {)" + medium + R"(}, "samples": "s.lsf"}]})";
}
const char* kLight = R"({"type": "point", "position": [3, 3, 3], "intensity": 10})";

// Class 4: a FIFO, a device, a directory: refused before anything opens them.
TEST(HostileInput, OnlyRegularFilesAreRead) {
    test::ScratchDir dir;
    const auto fifo = dir.path() / "fifo";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    EXPECT_CONTAINS(errorOf([&] { parseScene(fifo); }),
                    "fifo: cannot read scene file: it is a FIFO, not a regular file");
    EXPECT_CONTAINS(errorOf([&] { readSampleFile("/dev/zero"); }), "it is a character device, not a regular file");
    EXPECT_CONTAINS(errorOf([&] { readSampleFile(dir.path()); }), "it is a directory, not a regular file");
    std::vector<std::string> warnings;
    EXPECT_CONTAINS(errorOf([&] { loadClosedMesh(fifo, warnings); }), "cannot read mesh file: it is a FIFO");
    EXPECT_CONTAINS(errorOf([&] {
                        loadRawGrid("/dev/urandom", 2, 2, 2, Bounds3{Vec3(0), Vec3(1)});
                    }),
                    "/dev/urandom: cannot read density grid file: it is a character device");
    // The scene's fingerprint hashes the mesh: a FIFO mesh must not block the parser.
    const auto scene = dir.write("scene.json", sceneWith("[0, 0, 5]", kLight, fifo.string()));
    EXPECT_NO_THROW(parseScene(scene));
}

// Class 5: what a file claims is checked against its size and the budget first.
TEST(HostileInput, ClaimedSizesAreCheckedBeforeAllocating) {
    test::ScratchDir dir;
    std::vector<std::string> warnings;
    const auto ply =
        dir.write("bomb.ply",
                  "ply\nformat ascii 1.0\nelement vertex 1000000000000\nproperty float x\nproperty float y\n"
                  "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
                  "0 0 0\n3 0 0 0\n");
    EXPECT_CONTAINS(errorOf([&] { loadClosedMesh(ply, warnings); }), "bomb.ply: header claims 1000000000000 elements");
    const auto ply2 = dir.write("short.ply",
                                "ply\nformat binary_little_endian 1.0\nelement vertex 1000\nproperty float x\n"
                                "property float y\nproperty float z\nend_header\n");
    EXPECT_CONTAINS(errorOf([&] { loadClosedMesh(ply2, warnings); }),
                    "short.ply: PLY header claims elements of at least 12000 bytes");
    const auto off = dir.write("bomb.off", "OFF\n50000000 60000000 0\n0 0 0\n");
    EXPECT_CONTAINS(errorOf([&] { loadClosedMesh(off, warnings); }), "bomb.off: OFF header claims 50000000 vertices");

    // A sparse raw grid of 256 GiB: refused by its size, not read or hashed.
    const auto raw = dir.path() / "huge.raw";
    { std::ofstream(raw, std::ios::binary); }
    std::filesystem::resize_file(raw, uint64_t(256) << 30);
    EXPECT_CONTAINS(errorOf([&] {
                        loadRawGrid(raw, 4096, 4096, 4096, Bounds3{Vec3(0), Vec3(1)});
                    }),
                    "density grid would need 256 GiB, more than the memory budget of 4 GiB");

    // An OpenVDB file of a few KB whose active box is 1500^3 voxels: two voxels at opposite corners.
    openvdb::initialize();
    auto grid = openvdb::FloatGrid::create(0.0f);
    grid->setName("density");
    grid->tree().setValue(openvdb::Coord(0), 1.0f);
    grid->tree().setValue(openvdb::Coord(1499), 1.0f);
    const auto vdb = dir.path() / "tile.vdb";
    openvdb::io::File(vdb.string()).write({grid});
    ASSERT_LT(std::filesystem::file_size(vdb), 100000u);
    EXPECT_CONTAINS(errorOf([&] { loadVdbGrid(vdb, "density"); }),
                    "1500x1500x1500 voxels would need 12.6 GiB, more than the memory budget of 4 GiB");
}

// Class 3 and 6: coordinates and magnitudes beyond what single precision holds
// are refused with the limit named; a huge direction is still a direction.
TEST(HostileInput, OutOfRangeNumbersAreRefusedAndDirectionsNormalisedSafely) {
    test::ScratchDir dir;
    const std::string sphere = (test::modelsDir() / "sphere.obj").string();
    auto parse = [&](const std::string& text) { return parseSceneText(text, dir.path() / "scene.json"); };
    EXPECT_CONTAINS(errorOf([&] { parse(sceneWith("[0, 0, 1e19]", kLight, sphere)); }),
                    "/camera/position/2: must lie in [-1e+13, 1e+13] (got 1e+19)");
    EXPECT_CONTAINS(
        errorOf([&] {
            parse(sceneWith("[0, 0, 5]", R"({"type": "point", "position": [1e20, 0, 0], "intensity": 1e38})", sphere));
        }),
        "/lights/0/position/0: must lie in [-1e+13, 1e+13]");
    EXPECT_CONTAINS(
        errorOf([&] {
            parse(sceneWith("[0, 0, 5]", R"({"type": "point", "position": [3, 3, 3], "intensity": 1e300})", sphere));
        }),
        "/lights/0/intensity: must lie in [0, 1e+30]");
    EXPECT_CONTAINS(
        errorOf([&] {
            parse(sceneWith(
                "[0, 0, 5]", kLight, sphere,
                R"("sigma_t": 1, "albedo": 0.5, "density": {"type": "layers", "axis": "y", "values": [1, 1e300]})"));
        }),
        "/values/1: must lie in [0, 1e+30]");
    const SceneDesc huge = parse(
        sceneWith("[0, 0, 5]", R"({"type": "directional", "direction": [1e200, 0, 0], "irradiance": 1})", sphere));
    EXPECT_EQ(huge.lights[0].direction, Vec3(1, 0, 0));
    const SceneDesc tiny = parse(
        sceneWith("[0, 0, 5]", R"({"type": "directional", "direction": [1e-300, 0, 0], "irradiance": 1})", sphere));
    EXPECT_EQ(tiny.lights[0].direction, Vec3(1, 0, 0));
    std::vector<std::string> warnings;
    const auto far =
        dir.write("far.obj", "v 0 0 0\nv 1e19 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
    EXPECT_CONTAINS(errorOf([&] { loadClosedMesh(far, warnings); }), "vertex 1 lies farther than 1e13 from the origin");
    // sigma_t times the density must stay a float (class 6: it became inf in the sample file).
    ObjectDesc dense = test::simpleObject(sphere, 1e20);
    dense.medium.density.type = DensityDesc::Type::Layers;
    dense.medium.density.values = {1e20};
    EXPECT_CONTAINS(errorOf([&] { VolumeObject(dense, warnings); }),
                    "sigma_t times the density reaches 1e+40, above the 1e30");
}

// Class 6: the reference refuses an optical size its single-precision ray casting
// cannot resolve, instead of returning an image that grows with sigma_t.
TEST(HostileInput, ReferenceRefusesOpticalSizesItCannotResolve) {
    SceneDesc scene;
    scene.file = "scene.json";
    scene.camera.width = scene.camera.height = 4;
    scene.lights = {test::pointLight(Vec3(3.0), Rgb(10.0))};
    scene.objects = {test::simpleObject(test::modelsDir() / "sphere.obj", 1e10)};
    std::vector<std::string> warnings;
    const std::vector<VolumeObject> objects = loadObjects(scene, warnings);
    EXPECT_CONTAINS(errorOf([&] { ReferenceRenderer(scene, objects).render({}); }),
                    "--method reference: sigma_t times the object's size reaches 3.46e+10, beyond the 4e+06");
}

// Class 7: more lights than the blocker shadow maps hold are refused by name.
TEST(HostileInput, TooManyLightsAreRefusedNamingTheLimit) {
    std::string lights;
    for (size_t i = 0; i <= kMaxLights; ++i) lights += std::string(i ? ", " : "") + kLight;
    EXPECT_CONTAINS(errorOf([&] { parseSceneText(sceneWith("[0, 0, 5]", lights, "m.obj"), "scene.json"); }),
                    "scene.json: /lights: holds 257 lights; at most 256 are supported");
}

// Class 8: errors that named the wrong problem, were cut short or never came.
TEST(HostileInput, ErrorsSayWhatIsWrongInOneLine) {
    test::ScratchDir dir;
    std::vector<std::string> warnings;
    const auto obj = dir.write("index.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 9\n");
    EXPECT_CONTAINS(errorOf([&] { loadClosedMesh(obj, warnings); }),
                    "index.obj: line 6: face refers to vertex 9, but 4 vertices come before it");
    const auto tiny =
        dir.write("tiny.obj", "v 0 0 0\nv 1e-30 0 0\nv 0 1e-30 0\nv 0 0 1e-30\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
    EXPECT_CONTAINS(errorOf([&] { loadClosedMesh(tiny, warnings); }),
                    "tiny.obj: mesh is 1.73e-30 across; Lucent renders objects at least 1e-9 across");
    const auto om = dir.write("mesh.om", "OM");
    EXPECT_CONTAINS(errorOf([&] { loadClosedMesh(om, warnings); }), "unsupported mesh format '.om'");
    // A NUL or a newline in a name is shown, not obeyed.
    EXPECT_STREQ(Error(std::string("a\0b\nc", 5), "bad").what(), "a\\x00b\\x0ac: bad");
    // A key given twice would silently keep the later value.
    const std::string twice = sceneWith("[0, 0, 5]", kLight, "m.obj", R"("sigma_t": 2, "albedo": 0.5, "sigma_t": 200)");
    EXPECT_CONTAINS(errorOf([&] { parseSceneText(twice, "scene.json"); }),
                    "scene.json: /objects/medium: duplicate key 'sigma_t'");
    // A sample file whose header holds NaN.
    SampleSet set;
    set.bounds = Bounds3{Vec3(0.0), Vec3(std::nan(""))};
    writeSampleFile(dir.path() / "nan.lsf", set);
    EXPECT_CONTAINS(errorOf([&] { readSampleFile(dir.path() / "nan.lsf"); }),
                    "nan.lsf: sample file header has non-finite bounds");
}

// Class 1 at the level of the checks: identity, not names, decides.
TEST(HostileInput, OutputsAreComparedWithInputsByIdentity) {
    test::ScratchDir dir;
    const auto mesh = dir.write("mesh.obj", "v 0 0 0\n");
    std::filesystem::create_hard_link(mesh, dir.path() / "hard.lsf");
    std::filesystem::create_symlink(mesh, dir.path() / "soft.lsf");
    EXPECT_CONTAINS(errorOf([&] { checkOutputIsNoInput(dir.path() / "hard.lsf", {mesh}); }),
                    "hard.lsf: will not write over an input of this run");
    EXPECT_CONTAINS(errorOf([&] { checkOutputIsNoInput(dir.path() / "soft.lsf", {}); }),
                    "soft.lsf: will not write over a symbolic link");
    EXPECT_CONTAINS(errorOf([&] { checkOutputIsNoInput("/dev/null", {}); }), "will not write over a character device");
    EXPECT_NO_THROW(checkOutputIsNoInput(dir.path() / "new.lsf", {mesh}));
    EXPECT_CONTAINS(errorOf([&] {
                        checkOutputsDistinct({dir.path() / "a.lsf", dir.path() / "." / "a.lsf"});
                    }),
                    "is the output of two objects");
}

}  // namespace
}  // namespace lucent
