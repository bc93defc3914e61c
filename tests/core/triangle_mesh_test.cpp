#include "core/triangle_mesh.h"

#include <gtest/gtest.h>

#include "core/error.h"
#include "tests/support/test_support.h"

namespace lucent {
namespace {

// A tetrahedron with outward faces, in several formats.
const char* kTetraObj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
const char* kTetraOff = "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
const char* kTetraPly =
    "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
    "element face 4\nproperty list uchar int vertex_indices\nend_header\n"
    "0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";

std::string tetraStl() {
    const Vec3 p[4] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    const int f[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    std::string s = "solid t\n";
    for (const auto& t : f) {
        s += "facet normal 0 0 0\nouter loop\n";
        for (int k : t)
            s +=
                "vertex " + std::to_string(p[k].x) + " " + std::to_string(p[k].y) + " " + std::to_string(p[k].z) + "\n";
        s += "endloop\nendfacet\n";
    }
    return s + "endsolid t\n";
}

std::string loadError(const test::ScratchDir& dir, const std::string& name, const std::string& contents) {
    std::vector<std::string> warnings;
    try {
        loadClosedMesh(dir.write(name, contents), warnings);
    } catch (const Error& e) {
        return e.what();
    }
    return "no error";
}

TEST(TriangleMesh, LoadsEveryFormat) {
    test::ScratchDir dir;
    for (const auto& [name, text] : std::vector<std::pair<std::string, std::string>>{
             {"t.obj", kTetraObj}, {"t.off", kTetraOff}, {"t.ply", kTetraPly}, {"t.stl", tetraStl()}}) {
        std::vector<std::string> warnings;
        const TriangleMesh mesh = loadClosedMesh(dir.write(name, text), warnings);
        EXPECT_EQ(mesh.positions.size(), 4u) << name;
        EXPECT_EQ(mesh.triangles.size(), 4u) << name;
        EXPECT_NEAR(mesh.signedVolume(), 1.0 / 6.0, 1e-6) << name;
        EXPECT_TRUE(warnings.empty()) << name;
    }
}

TEST(TriangleMesh, FlipsInvertedOrientation) {
    test::ScratchDir dir;
    const char* inverted = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 4 2\nf 1 3 4\nf 2 4 3\n";
    std::vector<std::string> warnings;
    const TriangleMesh mesh = loadClosedMesh(dir.write("inv.obj", inverted), warnings);
    EXPECT_NEAR(mesh.signedVolume(), 1.0 / 6.0, 1e-12);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("orientation flipped"), std::string::npos);
}

TEST(TriangleMesh, DropsZeroAreaFacesWithAWarning) {
    test::ScratchDir dir;
    // A tetrahedron whose edge 1-2 is split by vertex 5 on one side only; the
    // zero-area face (1, 2, 5) closes the T-junction, so the mesh is closed.
    const char* withSliver =
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nv 0.5 0 0\n"
        "f 1 3 2\nf 1 5 4\nf 5 2 4\nf 1 4 3\nf 2 3 4\nf 1 2 5\n";
    std::vector<std::string> warnings;
    const TriangleMesh mesh = loadClosedMesh(dir.write("sliver.obj", withSliver), warnings);
    EXPECT_EQ(mesh.triangles.size(), 5u);
    EXPECT_NEAR(mesh.signedVolume(), 1.0 / 6.0, 1e-12);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("removed 1 zero-area face"), std::string::npos) << warnings[0];
}

TEST(TriangleMesh, RejectsBrokenMeshesWithOneLine) {
    test::ScratchDir dir;
    struct Case {
        std::string name, contents, message;
    };
    const std::vector<Case> cases = {
        {"hole.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\n", "mesh is not closed"},
        {"empty.obj", "# nothing\n", "mesh is empty"},
        {"nan.obj", "v 0 0 0\nv nan 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n", "non-finite"},
        // Three faces on one edge (two tetrahedra glued by an edge-sharing fin).
        {"fin.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nv 0 -1 0\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\nf 1 2 5\n",
         "mesh is not manifold"},
        // Its header claims more than its bytes can hold: refused before OpenMesh reads it.
        {"garbage.off", "OFF\n3 1\nbroken", "OFF header claims 3 vertices and 1 faces"},
        // A header that only contains OFF: OpenMesh's reader spun on it for minutes
        // in some runs (fuzz corpus d54e6e4c), so it never reaches OpenMesh.
        {"offp.off", std::string("OFFp\0 5 0 23\n", 13), "OFF header 'OFFp?' is not one Lucent reads"},
        {"bare.off", "OFF", "OFF file ends before its vertex and face counts"},
    };
    for (const Case& c : cases) {
        const std::string message = loadError(dir, c.name, c.contents);
        EXPECT_NE(message.find(c.name), std::string::npos) << message;
        EXPECT_NE(message.find(c.message), std::string::npos) << c.name << ": " << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;  // one line
    }
    std::vector<std::string> warnings;
    EXPECT_THROW(loadClosedMesh(dir.path() / "missing.obj", warnings), Error);
}

TEST(TriangleMesh, RejectsNanInBinaryStl) {
    test::ScratchDir dir;
    const float p[4][3] = {{0, 0, 0}, {NAN, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    const int f[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    std::string bytes(80, ' ');
    const uint32_t count = 4;
    bytes.append(reinterpret_cast<const char*>(&count), 4);
    for (const auto& t : f) {
        const float normal[3] = {0, 0, 0};
        bytes.append(reinterpret_cast<const char*>(normal), 12);
        for (int k : t) bytes.append(reinterpret_cast<const char*>(p[k]), 12);
        bytes.append(2, '\0');
    }
    const std::string message = loadError(dir, "nan.stl", bytes);
    EXPECT_NE(message.find("nan.stl"), std::string::npos) << message;
    EXPECT_NE(message.find("non-finite"), std::string::npos) << message;
}

TEST(TriangleMesh, RejectsTwoTetrahedraSharingAVertex) {
    test::ScratchDir dir;
    const char* bowtie =
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nv -1 0 0\nv 0 -1 0\nv 0 0 -1\n"
        "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n"
        "f 1 6 5\nf 1 5 7\nf 1 7 6\nf 5 6 7\n";
    const std::string message = loadError(dir, "bowtie.obj", bowtie);
    EXPECT_NE(message.find("not manifold"), std::string::npos) << message;
}

TEST(TriangleMesh, BundledModelsAreClosed) {
    for (const char* name : {"sphere.obj", "cube.obj", "torus.obj", "bunny.off"}) {
        std::vector<std::string> warnings;
        const TriangleMesh mesh = loadClosedMesh(test::modelsDir() / name, warnings);
        EXPECT_GT(mesh.signedVolume(), 0.0) << name;
    }
}

}  // namespace
}  // namespace lucent

namespace lucent {
namespace {

// Shading normals: sharp across a cube's 90-degree edges (every corner normal
// is its face's), smooth on a sphere (nearer the exact radial normal than the
// flat face normal, everywhere on each face we probe).
TEST(ShadingNormals, SharpAcrossCreasesAndSmoothElsewhere) {
    std::vector<std::string> warnings;
    const TriangleMesh cube = loadClosedMesh(test::modelsDir() / "cube.obj", warnings);
    const auto cubeCorners = cornerNormals(cube);
    for (size_t f = 0; f < cube.triangles.size(); ++f) {
        const Vec3 n = glm::normalize(cube.faceNormal(f));
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(glm::dot(cubeCorners[f][c], n), 1.0, 1e-12) << f;
    }
    const TriangleMesh sphere = loadClosedMesh(test::modelsDir() / "sphere.obj", warnings);
    const auto corners = cornerNormals(sphere);
    double flatError = 0.0, smoothError = 0.0;
    for (size_t f = 0; f < sphere.triangles.size(); f += 7) {
        const auto& t = sphere.triangles[f];
        // A point off the centroid, where interpolation matters.
        const Vec3 p = 0.6 * sphere.positions[t[0]] + 0.3 * sphere.positions[t[1]] + 0.1 * sphere.positions[t[2]];
        const Vec3 exact = glm::normalize(p);
        const Vec3 smooth = interpolatedNormal(sphere, corners[f], f, p);
        EXPECT_NEAR(glm::length(smooth), 1.0, 1e-12);
        flatError += 1.0 - glm::dot(glm::normalize(sphere.faceNormal(f)), exact);
        smoothError += 1.0 - glm::dot(smooth, exact);
    }
    EXPECT_LT(smoothError, 0.1 * flatError);
    // At a corner the interpolated normal is that corner's.
    const auto& t = sphere.triangles[0];
    EXPECT_NEAR(glm::dot(interpolatedNormal(sphere, corners[0], 0, sphere.positions[t[1]]), corners[0][1]), 1.0, 1e-12);
}

}  // namespace
}  // namespace lucent
