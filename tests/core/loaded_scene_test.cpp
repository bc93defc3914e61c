// loadScene takes an object's mesh from its sample file when the file was made
// for the present mesh file (same fingerprint), and reads the mesh file
// otherwise. The sample files here are written by hand, so each test knows
// which mesh the object must end up with.
#include "core/loaded_scene.h"

#include <gtest/gtest.h>

#include "core/error.h"
#include "core/sample_set.h"
#include "core/scene.h"
#include "tests/support/test_support.h"

namespace lucent {
namespace {

// A scene of one box [-1, 1]^3 read from box.obj, samples in box.lsf.
SceneDesc boxScene(const test::ScratchDir& dir) {
    test::writeBox(dir, "box.obj", Vec3(-1), Vec3(1));
    const auto file =
        dir.write("scene.json",
                  R"({"camera": {"position": [0, 0, 5], "target": [0, 0, 0], "fov_y": 40, "width": 64, "height": 64},
        "lights": [{"type": "point", "position": [3, 3, 3], "intensity": 1}],
        "objects": [{"mesh": "box.obj", "medium": {"sigma_t": 2, "albedo": 0.5}, "samples": "box.lsf"}]})");
    return parseScene(file);
}

// An empty sample set (optically thick: no samples needed) of that fingerprint.
SampleSet setFor(uint64_t fingerprint) {
    SampleSet s;
    s.sceneFingerprint = fingerprint;
    s.parameters.scheme = SampleScheme::OpticallyThick;
    s.bounds = Bounds3{Vec3(-1), Vec3(1)};
    return s;
}

// The mesh a sample file carries: half the size of box.obj, so that it shows.
TriangleMesh halfBox(const test::ScratchDir& dir) {
    std::vector<std::string> warnings;
    return loadClosedMesh(test::writeBox(dir, "half.obj", Vec3(-0.5), Vec3(0.5)), warnings);
}

TEST(LoadedScene, TakesTheMeshFromASampleFileMadeForThePresentMeshFile) {
    test::ScratchDir dir;
    const SceneDesc scene = boxScene(dir);
    SampleSet s = setFor(scene.objects[0].fingerprint);
    s.mesh = halfBox(dir);
    writeSampleFile(dir.path() / "box.lsf", s);
    const LoadedScene loaded = loadScene(scene, true);
    ASSERT_EQ(loaded.objects.size(), 1u);
    EXPECT_EQ(loaded.objects[0].mesh().bounds().max, Vec3(0.5));  // the sample file's, not box.obj's
    EXPECT_EQ(loaded.objects[0].mesh().triangles, s.mesh.triangles);
    EXPECT_TRUE(loaded.samples[0].mesh.triangles.empty());  // moved to the object, not held twice
    // Without sample files, the mesh file.
    EXPECT_EQ(loadScene(scene, false).objects[0].mesh().bounds().max, Vec3(1.0));
}

TEST(LoadedScene, ReadsTheMeshFileWhenTheSampleFileHoldsNone) {
    test::ScratchDir dir;
    const SceneDesc scene = boxScene(dir);
    writeSampleFile(dir.path() / "box.lsf", setFor(scene.objects[0].fingerprint));
    const LoadedScene loaded = loadScene(scene, true);
    EXPECT_EQ(loaded.objects[0].mesh().bounds().max, Vec3(1.0));
    EXPECT_EQ(loaded.objects[0].mesh().triangles.size(), 12u);
}

TEST(LoadedScene, AStaleSampleFileIsRefusedAndItsMeshNotTaken) {
    test::ScratchDir dir;
    const SceneDesc scene = boxScene(dir);
    SampleSet s = setFor(scene.objects[0].fingerprint + 1);
    s.mesh = halfBox(dir);
    writeSampleFile(dir.path() / "box.lsf", s);
    try {
        loadScene(scene, true);
        FAIL() << "a sample file of another fingerprint was taken";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("box.lsf: sample file was made for a different mesh or medium"),
                  std::string::npos)
            << e.what();
    }
}

TEST(LoadedScene, AMeshErrorIsToldBeforeASampleFileError) {
    test::ScratchDir dir;
    const SceneDesc scene = boxScene(dir);
    dir.write("box.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");  // open: a single triangle
    dir.write("box.lsf", "not a sample file");
    try {
        loadScene(scene, true);
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("box.obj: mesh is not closed"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace lucent
