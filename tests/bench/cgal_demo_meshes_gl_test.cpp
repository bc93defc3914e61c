// The accuracy bench's meshes from CGAL's demo archive: a tar.gz written here
// (ustar headers by hand, gzip by zlib) stands in for Debian's, so the reader
// is tested on every machine, with or without libcgal-demo.
#include <gtest/gtest.h>
#include <zlib.h>

#include <cstring>
#include <fstream>

#include "bench/cgal_demo_meshes.h"
#include "core/error.h"
#include "core/scene.h"
#include "core/triangle_mesh.h"
#include "tests/support/test_support.h"

namespace lucent {
namespace {

const char* kTetrahedron = "OFF\n4 4 0\n0 0 0\n2 0 0\n0 1 0\n0 0 0.5\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";

// One ustar entry: header, contents, padding to 512 bytes.
std::string tarEntry(const std::string& path, const std::string& contents) {
    std::string header(512, '\0');
    std::memcpy(&header[0], path.data(), path.size());
    char size[12];
    std::snprintf(size, sizeof size, "%011o", unsigned(contents.size()));
    std::memcpy(&header[124], size, 11);
    header[156] = '0';
    std::memcpy(&header[257], "ustar", 5);
    return header + contents + std::string((512 - contents.size() % 512) % 512, '\0');
}

std::filesystem::path writeArchive(const test::ScratchDir& dir) {
    const std::string tar = tarEntry("data/README", std::string(700, 'x')) +
                            tarEntry("data/meshes/tetra.off", kTetrahedron) + std::string(1024, '\0');
    const auto file = dir.path() / "data.tar.gz";
    gzFile out = gzopen(file.c_str(), "wb");
    gzwrite(out, tar.data(), unsigned(tar.size()));
    gzclose(out);
    return file;
}

TEST(CgalDemoMeshes, ExtractsTheNamedMeshAndRefusesTheRest) {
    test::ScratchDir dir;
    const auto archive = writeArchive(dir);
    const auto mesh = extractCgalDemoMesh("tetra", dir.path() / "out", archive);
    std::ifstream in(mesh);
    const std::string contents((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_EQ(contents, kTetrahedron);
    auto errorOf = [&](const std::string& name, const std::filesystem::path& from) {
        try {
            extractCgalDemoMesh(name, dir.path() / "out", from);
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_NE(errorOf("elephant", archive).find("holds no mesh 'elephant'"), std::string::npos);
    EXPECT_NE(errorOf("../tetra", archive).find("a name is letters, digits"), std::string::npos);
    EXPECT_NE(errorOf("tetra", dir.path() / "missing.tar.gz").find("libcgal-demo"), std::string::npos);
    EXPECT_FALSE(std::filesystem::exists(dir.path() / "out" / "elephant.off"));
}

// The scene made for a mesh frames it and gives it the optical radius asked for.
TEST(CgalDemoMeshes, TheSceneHasTheOpticalRadiusAskedFor) {
    test::ScratchDir dir;
    const auto mesh = extractCgalDemoMesh("tetra", dir.path(), writeArchive(dir));
    const SceneDesc scene = parseScene(writeMeshScene(mesh, dir.path(), 1.5, 64));
    ASSERT_EQ(scene.objects.size(), 1u);
    // The box is 2 x 1 x 0.5: the smallest half-extent is 0.25.
    EXPECT_NEAR(scene.objects[0].medium.sigmaT.r * 0.25, 1.5, 1e-12);
    EXPECT_EQ(scene.camera.width, 64);
    EXPECT_EQ(scene.objects[0].mesh, mesh);
}

}  // namespace
}  // namespace lucent
