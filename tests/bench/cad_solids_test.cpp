// The CAD test solids of models/cad/, exported by Debian's openscad: each is a
// closed mesh, and those whose volume has a closed form hold that volume, so the
// accuracy bench measures the solid each .scad says it is.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "bench/cad_solids.h"
#include "core/error.h"
#include "core/triangle_mesh.h"
#include "tests/support/test_support.h"

namespace lucent {
namespace {

const std::filesystem::path kCadDir = std::filesystem::path(LUCENT_SOURCE_DIR) / "models" / "cad";

// OpenSCAD's cylinder of $fn sides is the regular polygon inscribed in its circle.
double polygonArea(int sides, double radius) { return 0.5 * sides * radius * radius * std::sin(2.0 * M_PI / sides); }

TEST(CadSolids, EachModelExportsAClosedMeshOfItsVolume) {
    // Volumes by hand from the .scad sources (units^3).
    const struct {
        const char* name;
        double volume;  // 0: no closed form (spheres, hulls, letters)
    } solids[] = {
        {"block", 60.0 * 40 * 30},
        {"plate-holes", 80.0 * 60 * 12 - 6 * polygonArea(40, 6.0) * 12},
        // The slot is 12 wide, 17 deep inside the block; the pocket 10 x 8 x 10.
        {"slotted-block", 60.0 * 40 * 30 - 12.0 * 40 * 17 - 10.0 * 8 * 10},
        // Base, four ribs along y and three along x, minus the twelve crossings counted twice.
        {"ribs", 64.0 * 64 * 4 + 4 * 2.0 * 64 * 16 + 3 * 64.0 * 2 * 16 - 12 * 2.0 * 2 * 16},
        {"rounded-block", 0.0},
        {"die", 0.0},
        {"letters", 0.0},
    };
    test::ScratchDir dir;
    size_t models = 0;
    for (const auto& entry : std::filesystem::directory_iterator(kCadDir))
        models += entry.path().extension() == ".scad";
    EXPECT_EQ(models, std::size(solids)) << "a model in models/cad/ is not checked here";
    for (const auto& solid : solids) {
        SCOPED_TRACE(solid.name);
        const auto stl = exportScadSolid(kCadDir / (std::string(solid.name) + ".scad"), dir.path());
        std::vector<std::string> warnings;
        const TriangleMesh mesh = loadClosedMesh(stl, warnings);
        EXPECT_GT(mesh.signedVolume(), 0.0);
        if (solid.volume > 0.0) {
            EXPECT_NEAR(mesh.signedVolume(), solid.volume, 1e-4 * solid.volume);
        }
        EXPECT_FALSE(std::filesystem::exists(dir.path() / (std::string(solid.name) + ".partial.stl")));
    }
}

TEST(CadSolids, ABadModelIsOneErrorAndNoMesh) {
    test::ScratchDir dir;
    auto errorOf = [&](const std::filesystem::path& scad) {
        try {
            exportScadSolid(scad, dir.path() / "out");
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    const auto broken = dir.path() / "broken.scad";
    std::ofstream(broken) << "cube([1, 2, 3]\n";  // unclosed parenthesis
    EXPECT_NE(errorOf(broken).find("openscad failed"), std::string::npos) << errorOf(broken);
    EXPECT_FALSE(std::filesystem::exists(dir.path() / "out" / "broken.stl"));
    EXPECT_FALSE(std::filesystem::exists(dir.path() / "out" / "broken.partial.stl"));
    EXPECT_NE(errorOf(dir.path() / "missing.scad").find("missing.scad"), std::string::npos);
    EXPECT_NE(errorOf(dir.path()).find("ends in .scad"), std::string::npos);
    std::filesystem::create_directories(dir.path() / "folder.scad");
    EXPECT_NE(errorOf(dir.path() / "folder.scad").find("folder.scad"), std::string::npos);
}

}  // namespace
}  // namespace lucent
