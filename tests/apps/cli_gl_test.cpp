// The lucent command on bad input: one "lucent: error:" line naming the file and
// the problem, a non-zero exit, and no output file left behind.
#include <gtest/gtest.h>
#include <openvdb/openvdb.h>

#include <sys/stat.h>

#include <fstream>
#include <iterator>

#include "core/image.h"
#include "tests/support/test_support.h"

namespace lucent {
namespace {

const char* kTetra = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";

std::string scene(const std::string& mesh, const std::string& medium = R"("sigma_t": 2, "albedo": 0.5)") {
    return R"({"camera": {"position": [0, 0, 5], "target": [0, 0, 0], "fov_y": 40, "width": 16, "height": 16},
               "lights": [{"type": "point", "position": [3, 3, 3], "intensity": 10}],
               "objects": [{"mesh": ")" +
           mesh + R"(", "medium": {)" + medium + R"(}, "samples": "out.lsf"}]})";
}

class BadInput : public ::testing::Test {
protected:
    // Runs `lucent ARGS` and checks the contract; returns the error line.
    std::string expectFailure(const std::string& args, const std::string& mustMention,
                              const std::string& mustNotExist = "out.lsf", const std::string& environment = "") {
        const auto result = test::runLucent(args, environment);
        EXPECT_NE(result.exitCode, 0) << args;
        EXPECT_EQ(result.stderrText.rfind("lucent: error: ", 0), 0u) << result.stderrText;
        EXPECT_EQ(std::count(result.stderrText.begin(), result.stderrText.end(), '\n'), 1) << result.stderrText;
        EXPECT_NE(result.stderrText.find(mustMention), std::string::npos) << result.stderrText;
        EXPECT_FALSE(std::filesystem::exists(dir.path() / mustNotExist)) << mustNotExist;
        for (const auto& entry : std::filesystem::directory_iterator(dir.path()))
            EXPECT_EQ(entry.path().string().find(".tmp"), std::string::npos) << entry.path();
        return result.stderrText;
    }
    std::string preprocess(const std::string& sceneText) {
        return "preprocess " + dir.write("scene.json", sceneText).string() + " --quality draft --samples 200";
    }
    test::ScratchDir dir;
};

TEST_F(BadInput, MissingMesh) {
    const std::string line = expectFailure(preprocess(scene("absent.obj")), "absent.obj: cannot open mesh file");
    EXPECT_NE(line.find("scene.json: /objects/0: "), std::string::npos) << line;
}

TEST_F(BadInput, MeshWithAHole) {
    dir.write("hole.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\n");
    expectFailure(preprocess(scene("hole.obj")), "hole.obj: mesh is not closed");
}

TEST_F(BadInput, NonManifoldMesh) {
    dir.write("bowtie.obj",
              "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nv -1 0 0\nv 0 -1 0\nv 0 0 -1\n"
              "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\nf 1 6 5\nf 1 5 7\nf 1 7 6\nf 5 6 7\n");
    expectFailure(preprocess(scene("bowtie.obj")), "bowtie.obj: mesh is not manifold");
}

TEST_F(BadInput, EmptyMesh) {
    dir.write("empty.obj", "# no geometry\n");
    expectFailure(preprocess(scene("empty.obj")), "empty.obj: mesh is empty");
}

TEST_F(BadInput, NanCoordinates) {
    dir.write("nan.obj", "v 0 0 0\nv nan 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
    expectFailure(preprocess(scene("nan.obj")), "nan.obj: a vertex has non-finite or malformed coordinates");
}

TEST_F(BadInput, MalformedJson) { expectFailure(preprocess("{\"camera\": "), "scene.json: malformed JSON"); }

TEST_F(BadInput, UnknownKey) {
    dir.write("t.obj", kTetra);
    expectFailure(preprocess(scene("t.obj", R"("sigma_t": 2, "albedo": 0.5, "sigma_s": 1)")),
                  "scene.json: /objects/0/medium/sigma_s: unknown key");
}

TEST_F(BadInput, NegativeSigmaT) {
    dir.write("t.obj", kTetra);
    expectFailure(preprocess(scene("t.obj", R"("sigma_t": -2, "albedo": 0.5)")),
                  "scene.json: /objects/0/medium/sigma_t: must lie in");
}

TEST_F(BadInput, AlbedoAboveOne) {
    dir.write("t.obj", kTetra);
    expectFailure(preprocess(scene("t.obj", R"("sigma_t": 2, "albedo": [0.5, 1.2, 0.5])")),
                  "scene.json: /objects/0/medium/albedo/1: must lie in [0, 1]");
}

TEST_F(BadInput, BlockerOutsideItsObject) {
    dir.write("t.obj", kTetra);
    dir.write("far.obj", "v 5 0 0\nv 6 0 0\nv 5 1 0\nv 5 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
    expectFailure(preprocess(scene("t.obj", R"("sigma_t": 2, "albedo": 0.5, "blockers": ["far.obj"])")),
                  "far.obj: blocker is not inside its object");
}

TEST_F(BadInput, GridSizeDoesNotMatchDims) {
    dir.write("t.obj", kTetra);
    dir.write("d.raw", std::string(7 * 4, '\0'));
    expectFailure(preprocess(scene("t.obj", R"("sigma_t": 2, "albedo": 0.5,
        "density": {"type": "grid", "file": "d.raw", "dims": [2, 2, 2], "bounds": [[0, 0, 0], [1, 1, 1]]})")),
                  "d.raw: grid file holds 28 bytes but dims [2, 2, 2] need 32");
}

TEST_F(BadInput, UnwritableOutputPath) {
    const auto sceneFile = dir.write("scene.json", scene((test::modelsDir() / "cube.obj").string()));
    expectFailure("render " + sceneFile.string() + " -o " + (dir.path() / "no-such-dir" / "x.png").string() +
                      " --width 8 --height 8",
                  "x.png: cannot write");
    const std::string samples = (dir.path() / "no-such-dir" / "s.lsf").string();
    std::string text = scene((test::modelsDir() / "cube.obj").string());
    text.replace(text.find("out.lsf"), 7, samples);
    expectFailure(preprocess(text), "s.lsf: cannot write");
}

// --method ss needs the object's sample file, whole and made for it.
class BadSampleFile : public BadInput {
protected:
    void SetUp() override {
        sceneFile = dir.write("scene.json", scene((test::modelsDir() / "sphere.obj").string()));
        const auto run = test::runLucent("preprocess " + sceneFile.string() + " --quality draft --samples 300");
        ASSERT_EQ(run.exitCode, 0) << run.stderrText;
    }
    std::string render(const std::string& extra = "") {
        return "render " + sceneFile.string() + " -o " + (dir.path() / "img.png").string() +
               " --method ss --width 16 --height 16 " + extra;
    }
    std::filesystem::path sceneFile;
};

#ifdef LUCENT_HAVE_OPENCL
TEST_F(BadSampleFile, LblWithoutAnOpenClDeviceSaysSoAndWritesNothing) {
    // The ICD loader reads its vendor list from OCL_ICD_VENDORS: an empty directory lists no platform.
    const auto empty = dir.path() / "no-icds";
    std::filesystem::create_directory(empty);
    std::string args = render();
    args.replace(args.find("--method ss"), 11, "--method lbl");
    expectFailure(args, "method 'lbl' cannot run here: no OpenCL device found", "img.png",
                  "OCL_ICD_VENDORS=" + empty.string());
}
#endif

TEST_F(BadSampleFile, Truncated) {
    std::filesystem::resize_file(dir.path() / "out.lsf", std::filesystem::file_size(dir.path() / "out.lsf") - 10);
    expectFailure(render(), "out.lsf: sample file holds", "img.png");
}

TEST_F(BadSampleFile, Missing) {
    std::filesystem::remove(dir.path() / "out.lsf");
    expectFailure(render(), "out.lsf: cannot open sample file", "img.png");
}

TEST_F(BadSampleFile, MadeForAnotherMedium) {
    std::string text = scene((test::modelsDir() / "sphere.obj").string(), R"("sigma_t": 3, "albedo": 0.5)");
    dir.write("scene.json", text);
    expectFailure(render(), "out.lsf: sample file was made for a different mesh or medium", "img.png");
}

TEST_F(BadSampleFile, NoUsableGlContextSaysWhichBackend) {
    // glvnd finds no EGL vendor library: EGL cannot give a display.
    expectFailure(render("--backend egl"), "no usable OpenGL context: egl: ", "img.png",
                  "__EGL_VENDOR_LIBRARY_FILENAMES=/nonexistent.json");
}

TEST_F(BadInput, UnknownSubcommandOption) {
    expectFailure("preprocess " + dir.write("scene.json", "{}").string() + " --quality ultra", "quality");
}

TEST_F(BadInput, ShOrderBeyondWhatTheRuntimeEvaluates) {
    expectFailure("preprocess " + dir.write("scene.json", "{}").string() + " --sh-order 9", "--sh-order");
}

TEST_F(BadInput, SceneNamesAMethodThisBuildLacks) {
    std::string text = scene((test::modelsDir() / "sphere.obj").string());
    text.insert(text.rfind('}'), R"(, "render": {"method": "dipole"})");
#ifdef LUCENT_HAVE_OPENCL
    const std::string built = "ss, reference, path, lbl, mdom, auto";
#else
    const std::string built = "ss, reference, path, auto";
#endif
    expectFailure("render " + dir.write("scene.json", text).string() + " -o " + (dir.path() / "img.png").string(),
                  "scene.json: /render/method: method 'dipole' is not built into this binary (built: " + built + ")",
                  "img.png");
}

TEST_F(BadInput, TransportProblemOutOfRange) {
    const auto file = dir.write("problem.json", R"({"domain": {"min": [0, 0, 0], "max": [1, 1, 1], "cells": [2, 2, 2]},
        "regions": [{"min": [0, 0, 0], "max": [1, 1, 1], "sigma_t": 1, "sigma_s": 2}], "points": [[0.5, 0.5, 0.5]]})");
    expectFailure("transport " + file.string() + " -o " + (dir.path() / "flux.csv").string(),
                  "problem.json: /regions/0: sigma_s (2) exceeds sigma_t (1)", "flux.csv");
}

TEST_F(BadInput, TransportOutputOverItsProblem) {
    const auto file = dir.write("problem.json", R"({"domain": {"min": [0, 0, 0], "max": [1, 1, 1], "cells": [2, 2, 2]},
        "regions": [], "points": [[0.5, 0.5, 0.5]]})");
    const auto size = std::filesystem::file_size(file);
    expectFailure("transport " + file.string() + " -o " + file.string(), "problem.json", "flux.csv");
    EXPECT_EQ(std::filesystem::file_size(file), size);
}

// lucent transport end to end: an infinite medium (reflecting faces) with a
// uniform source, whose flux is q / sigma_a = 2 / 0.25 = 8 exactly.
TEST(Cli, TransportWritesTheFluxAtThePoints) {
    test::ScratchDir dir;
    const auto file = dir.write("problem.json", R"({"domain": {"min": [0, 0, 0], "max": [1, 1, 1], "cells": [3, 3, 3]},
        "boundary": {"x-": "reflective", "x+": "reflective", "y-": "reflective", "y+": "reflective",
                     "z-": "reflective", "z+": "reflective"},
        "regions": [{"min": [0, 0, 0], "max": [1, 1, 1], "sigma_t": 1, "sigma_s": 0.75, "g": 0.5, "source": 2}],
        "points": [[0.5, 0.5, 0.5], [0.1, 0.9, 0.2]],
        "solver": {"directions": 24, "bands": 4, "tolerance": 1e-6}})");
    const auto run = test::runLucent("transport " + file.string() + " -o " + (dir.path() / "flux.csv").string());
#ifdef LUCENT_HAVE_OPENCL
    ASSERT_EQ(run.exitCode, 0) << run.stderrText;
    std::ifstream csv(dir.path() / "flux.csv");
    std::string header;
    std::getline(csv, header);
    EXPECT_EQ(header, "x,y,z,flux");
    const auto rows = test::readCsv(dir.path() / "flux.csv");
    ASSERT_EQ(rows.size(), 2u);
    EXPECT_EQ(rows[1][0], "0.1");
    for (const auto& row : rows) EXPECT_NEAR(std::stod(row[3]), 8.0, 8e-3);
#else
    EXPECT_NE(run.exitCode, 0);
    EXPECT_NE(run.stderrText.find("needs OpenCL"), std::string::npos) << run.stderrText;
#endif
}

#ifdef LUCENT_HAVE_OPENCL
// --vdb: the flux in every cell as an OpenVDB grid, placed in the problem's
// space (cells of 0.5 x 0.25 x 1 from (-1, 0, 2)): read at each point, it is
// the flux the CSV gives there; the source's corner is the brightest.
TEST(Cli, TransportWritesTheWholeVolumeAsOpenVdb) {
    test::ScratchDir dir;
    const auto file = dir.write("problem.json", R"({"domain": {"min": [-1, 0, 2], "max": [1, 1, 4], "cells": [4, 4, 2]},
        "regions": [{"min": [-1, 0, 2], "max": [1, 1, 4], "sigma_t": 1, "sigma_s": 0.5},
                    {"min": [-1, 0, 2], "max": [-0.5, 0.25, 3], "sigma_t": 1, "sigma_s": 0.5, "source": 3}],
        "points": [[-0.75, 0.125, 2.5], [0.75, 0.875, 3.5], [0.2, 0.6, 2.1]],
        "solver": {"directions": 24, "bands": 2}})");
    const auto csv = dir.path() / "flux.csv", vdb = dir.path() / "flux.vdb";
    const auto run = test::runLucent("transport " + file.string() + " -o " + csv.string() + " --vdb " + vdb.string());
    ASSERT_EQ(run.exitCode, 0) << run.stderrText;
    const auto rows = test::readCsv(csv);
    ASSERT_EQ(rows.size(), 3u);
    openvdb::initialize();
    openvdb::io::File in(vdb.string());
    in.open();
    const auto grid = openvdb::gridPtrCast<openvdb::FloatGrid>(in.readGrid("flux"));
    in.close();
    ASSERT_TRUE(grid);
    for (const auto& row : rows) {
        const openvdb::Vec3d world(std::stod(row[0]), std::stod(row[1]), std::stod(row[2]));
        const openvdb::Coord cell = grid->transform().worldToIndexCellCentered(world);
        EXPECT_NEAR(grid->tree().getValue(cell), std::stod(row[3]), 1e-5 * std::stod(row[3]))
            << row[0] << " " << row[1];
    }
    EXPECT_GT(std::stod(rows[0][3]), 2.0 * std::stod(rows[1][3]));
    EXPECT_EQ(grid->activeVoxelCount(), openvdb::Index64(4 * 4 * 2));
    // A name that is no OpenVDB file is refused before the solve, and nothing is written.
    const auto refused = test::runLucent("transport " + file.string() + " -o " + (dir.path() / "b.csv").string() +
                                         " --vdb " + (dir.path() / "b.exr").string());
    EXPECT_NE(refused.exitCode, 0);
    EXPECT_NE(refused.stderrText.find("must end in .vdb"), std::string::npos) << refused.stderrText;
    EXPECT_FALSE(std::filesystem::exists(dir.path() / "b.csv"));
}
#endif

TEST(Cli, HelpOffersOnlyTheMethodsThisBuildHas) {
    const auto help = test::runLucent("render --help");
    ASSERT_EQ(help.exitCode, 0) << help.stderrText;
#ifdef LUCENT_HAVE_OPENCL
    EXPECT_NE(help.stdoutText.find("--method TEXT:{ss,reference,path,lbl,mdom,auto}"), std::string::npos)
        << help.stdoutText;
#else
    EXPECT_NE(help.stdoutText.find("--method TEXT:{ss,reference,path,auto}"), std::string::npos) << help.stdoutText;
    EXPECT_EQ(help.stdoutText.find("lbl"), std::string::npos);
    EXPECT_EQ(help.stdoutText.find("mdom"), std::string::npos);
#endif
}

TEST(Cli, AutoSaysWhatItChoseAndWhy) {
    test::ScratchDir dir;
    const auto sceneFile = dir.write("scene.json", scene((test::modelsDir() / "sphere.obj").string()));
    ASSERT_EQ(test::runLucent("preprocess " + sceneFile.string() + " --quality draft --samples 300").exitCode, 0);
    const auto run = test::runLucent("render " + sceneFile.string() + " -o " + (dir.path() / "a.pfm").string() +
                                     " --method auto --width 8 --height 8");
    ASSERT_EQ(run.exitCode, 0) << run.stderrText;
    // Albedo 0.5: single scattering alone is far from full transport (docs/accuracy.md).
#ifdef LUCENT_HAVE_OPENCL
    EXPECT_NE(run.stderrText.find("method lbl on "), std::string::npos) << run.stderrText;
    EXPECT_NE(run.stderrText.find(", chosen by auto: albedo 0.50: single scattering alone leaves out the light "
                                  "scattered more than once"),
              std::string::npos)
        << run.stderrText;
#else
    EXPECT_NE(run.stderrText.find("method ss on "), std::string::npos) << run.stderrText;
    EXPECT_NE(run.stderrText.find("this build cannot add it"), std::string::npos) << run.stderrText;
#endif
}

// ---- Hostile input through the command (docs/robustness.md) -------------------

// Class 1: no output may replace an input, serve two objects or replace a link.
TEST_F(BadInput, PreprocessNeverWritesOverItsInputs) {
    const std::string sphere = (test::modelsDir() / "sphere.obj").string();
    dir.write("mesh.obj", kTetra);
    std::string overMesh = scene("mesh.obj");
    overMesh.replace(overMesh.find("out.lsf"), 7, "mesh.obj");
    const auto before = std::filesystem::file_size(dir.path() / "mesh.obj");
    expectFailure("preprocess " + dir.write("scene.json", overMesh).string(),
                  "will not write over an input of this run");
    EXPECT_EQ(std::filesystem::file_size(dir.path() / "mesh.obj"), before);
    std::string overScene = scene(sphere);
    overScene.replace(overScene.find("out.lsf"), 7, "scene.json");
    const auto sceneFile = dir.write("scene.json", overScene);
    const auto sceneSize = std::filesystem::file_size(sceneFile);
    expectFailure("preprocess " + sceneFile.string(), "scene.json: will not write over an input of this run");
    EXPECT_EQ(std::filesystem::file_size(sceneFile), sceneSize);
    std::filesystem::create_symlink(dir.path() / "elsewhere.lsf", dir.path() / "out.lsf");
    expectFailure(preprocess(scene(sphere)), "out.lsf: will not write over a symbolic link", "elsewhere.lsf");
    EXPECT_TRUE(std::filesystem::is_symlink(dir.path() / "out.lsf"));
}

TEST_F(BadInput, TwoObjectsSharingASampleFileAreRefused) {
    const std::string object = R"({"mesh": ")" + (test::modelsDir() / "sphere.obj").string() +
                               R"(", "medium": {"sigma_t": 2, "albedo": 0.5}, "samples": "out.lsf"})";
    std::string text = scene((test::modelsDir() / "sphere.obj").string());
    text.replace(text.rfind("]}"), 2, ", " + object + "]}");
    expectFailure(preprocess(text), "out.lsf: is the output of two objects");
}

TEST_F(BadInput, AFailingObjectLeavesNoSampleFileOfAnother) {
    const std::string good = R"({"mesh": ")" + (test::modelsDir() / "sphere.obj").string() +
                             R"(", "medium": {"sigma_t": 2, "albedo": 0.5}, "samples": "first.lsf"})";
    // A sliver 1e-4 thick holds no offset layer: preprocessing fails on it, after the sphere.
    dir.write("sliver.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1e-4\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
    const std::string sliver =
        R"({"mesh": "sliver.obj", "medium": {"sigma_t": 2, "albedo": 0.5}, "samples": "second.lsf"})";
    std::string text = scene("unused");
    text.replace(text.find("\"objects\": ["), std::string::npos, "\"objects\": [" + good + ", " + sliver + "]}");
    const auto run = test::runLucent(preprocess(text));  // progress lines come first, the error last
    EXPECT_NE(run.exitCode, 0);
    EXPECT_NE(run.stderrText.find("lucent: error: " + (dir.path() / "sliver.obj").string() +
                                  ": object is too thin for a single offset layer"),
              std::string::npos)
        << run.stderrText;
    EXPECT_FALSE(std::filesystem::exists(dir.path() / "first.lsf"));
    EXPECT_FALSE(std::filesystem::exists(dir.path() / "second.lsf"));
}

TEST_F(BadInput, RenderNeverWritesOverItsInputs) {
    // An image named like the mesh, through a hard link: identity decides, not the name.
    dir.write("mesh.obj", kTetra);
    std::filesystem::create_hard_link(dir.path() / "mesh.obj", dir.path() / "image.pfm");
    const auto sceneFile = dir.write("scene.json", scene("mesh.obj"));
    expectFailure("render " + sceneFile.string() + " --method reference -o " + (dir.path() / "image.pfm").string(),
                  "image.pfm: will not write over an input of this run", "img.png");
    EXPECT_EQ(std::filesystem::file_size(dir.path() / "mesh.obj"), std::string(kTetra).size());
}

// Class 4: a FIFO or a device as any input ends in an error, not a hang.
TEST_F(BadInput, FifosAndDevicesAreRefusedNotWaitedOn) {
    const auto fifo = dir.path() / "fifo";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    expectFailure("preprocess " + dir.write("scene.json", scene(fifo.string())).string(),
                  "fifo: cannot read mesh file: it is a FIFO");
    expectFailure("preprocess " + fifo.string(), "fifo: cannot read scene file: it is a FIFO");
    expectFailure("info /dev/zero", "/dev/zero: cannot read sample file: it is a character device");
    expectFailure("info " + dir.path().string(), "cannot read sample file: it is a directory");
    expectFailure("view " + dir.write("v.json", scene("m.obj")).string() + " --script /dev/urandom",
                  "/dev/urandom: cannot read viewer script: it is a character device");
    expectFailure("view " + dir.path().string() + "/v.json --script " + fifo.string(),
                  "cannot read viewer script: it is a FIFO");
}

// An environment map that is no map, or that ends early: one line naming it, no image.
TEST_F(BadInput, AnEnvironmentMapThatIsNoneIsRefusedNamingIt) {
    std::string text = scene((test::modelsDir() / "sphere.obj").string());
    text.replace(text.find("\"lights\": ["), 11, R"("lights": [{"type": "environment", "file": "sky.hdr"}, )");
    const std::string s = dir.write("scene.json", text).string();
    dir.write("sky.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 2 +X 4\n");
    expectFailure("render " + s + " --method path -o x.png", "sky.hdr: Radiance HDR file ends before its last texel",
                  "x.png");
    dir.write("sky.hdr", "GIF89a");
    expectFailure("render " + s + " --method reference -o x.png", "sky.hdr: not a Radiance HDR", "x.png");
}

// Class 4 and 8: every number on the command line is finite and in range.
TEST_F(BadInput, NumbersOnTheCommandLineAreFiniteAndInRange) {
    const std::string s = dir.write("scene.json", scene("m.obj")).string();
    expectFailure("render " + s + " -o x.png --tolerance nan", "--tolerance: 'nan' is not a number in [1e-08, 0.5]",
                  "x.png");
    expectFailure("render " + s + " -o x.png --noise inf", "--noise: 'inf' is not a number in [0, 1]", "x.png");
    expectFailure("render " + s + " -o x.png --directions 50", "--directions: '50' is not one of 24, 48, 80, 120, 168",
                  "x.png");
    expectFailure("render " + s + " -o x.png --exposure inf", "--exposure: 'inf' is not a finite number", "x.png");
    expectFailure("preprocess " + s + " --width-factor nan", "--width-factor: 'nan' is not a finite number");
    expectFailure("preprocess " + s + " --seed 18446744073709551616",
                  "--seed: '18446744073709551616' is not a whole number");
    expectFailure("bench accuracy " + s + " --tolerance -inf", "--tolerance: '-inf' is not a finite number");
}

// A method's options belong to it: given to another method they are an error
// naming the methods that take them, not silently ignored.
TEST_F(BadInput, AnOptionOfAnotherMethodIsAnError) {
    const std::string s = dir.write("scene.json", scene("m.obj")).string();
    expectFailure("render " + s + " -o x.png --method reference --samples 8",
                  "--samples is an option of --method path, not of reference", "x.png");
    expectFailure("render " + s + " -o x.png --method path --light sh",
                  "--light is an option of --method ss, lbl, mdom, not of path", "x.png");
}

// docs/methods.md is the reference of the methods' options: the output of
// `lucent methods`, built from their declarations, word for word.
TEST(Cli, MethodsPageIsWhatTheDeclarationsSay) {
    const auto run = test::runLucent("methods");
    ASSERT_EQ(run.exitCode, 0) << run.stderrText;
    std::ifstream in(test::sourceDir() / "docs" / "methods.md");
    const std::string page((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
#ifdef LUCENT_HAVE_OPENCL
    EXPECT_EQ(run.stdoutText, page) << "regenerate it: build/bin/lucent methods > docs/methods.md";
#else
    EXPECT_EQ(run.stdoutText, page.substr(0, page.find("\n## lbl") + 1));  // the page less the OpenCL methods
#endif
}

// Class 2: the plot script gets the output directory as one argument; no shell
// ever sees it. The sweep itself runs at draft quality on the cube.
TEST(Cli, BenchAccuracyRunsNoShellAndWritesItsPlots) {
    test::ScratchDir dir;
    const auto sceneFile =
        dir.write("scene.json", scene((test::modelsDir() / "cube.obj").string(), R"("sigma_t": 1, "albedo": 0.5)"));
    const std::string hostile = (dir.path() / "out'; touch PWNED; '").string();
    const auto run = test::runLucent("bench accuracy " + sceneFile.string() +
                                         " --quality draft --knobs cutoff --size 8 "
                                         "--frames 1 -o \"" +
                                         hostile + "\"",
                                     "cd " + dir.path().string() + " &&");
    ASSERT_EQ(run.exitCode, 0) << run.stderrText;
    EXPECT_FALSE(std::filesystem::exists(dir.path() / "PWNED"));
    const auto rows = test::readCsv(std::filesystem::path(hostile) / "accuracy.csv");
    EXPECT_EQ(rows.size(), 5u);  // five cut-offs
    for (const char* plot : {"accuracy-pareto.png", "accuracy-knobs.png"})
        EXPECT_GT(std::filesystem::file_size(std::filesystem::path(hostile) / plot), 1000u) << plot;
}

// --method path through the command: no sample file needed; the seed and the
// collision count reach the tracer (a different seed, a different image).
TEST(Cli, PathTracerRendersWithItsOptions) {
    test::ScratchDir dir;
    const auto sceneFile = dir.write("scene.json", scene((test::modelsDir() / "sphere.obj").string()));
    auto render = [&](const std::string& name, const std::string& options) {
        const auto run = test::runLucent("render " + sceneFile.string() + " --method path --width 8 --height 8 -o " +
                                         (dir.path() / name).string() + " " + options);
        EXPECT_EQ(run.exitCode, 0) << run.stderrText;
        EXPECT_NE(run.stderrText.find("method path"), std::string::npos) << run.stderrText;
        return readPfm(dir.path() / name);
    };
    const Image a = render("a.pfm", "--samples 4 --seed 5"), b = render("b.pfm", "--samples 4 --seed 5 --threads 1");
    const Image c = render("c.pfm", "--samples 4 --seed 6"),
                single = render("s.pfm", "--samples 4 --seed 5 --max-scatter 1");
    EXPECT_EQ(a.pixels, b.pixels);
    EXPECT_NE(a.pixels, c.pixels);
    double all = 0.0, one = 0.0;
    for (size_t i = 0; i < a.pixels.size(); ++i) all += a.pixels[i].g, one += single.pixels[i].g;
    EXPECT_GT(all, one);  // albedo 0.5: the higher orders add light
    const auto bad = test::runLucent("render " + sceneFile.string() + " --method path -o x.pfm --samples 0");
    EXPECT_NE(bad.exitCode, 0);
}

// A glTF file goes wherever a scene file goes: Blender's own export
// (tests/data/gltf/) is preprocessed beside itself and rendered, its camera
// picked by name; a camera it lacks is one error line.
TEST(Cli, ABlenderExportedGltfIsPreprocessedAndRenderedAsASceneIs) {
    test::ScratchDir dir;
    const auto model = dir.path() / "jade.glb";
    std::filesystem::copy_file(test::sourceDir() / "tests/data/gltf/blender-cube.glb", model);
    const auto pre = test::runLucent("preprocess " + model.string() + " --quality draft");
    ASSERT_EQ(pre.exitCode, 0) << pre.stderrText;
    EXPECT_TRUE(std::filesystem::is_regular_file(dir.path() / "jade.Jade.lsf")) << pre.stderrText;
    EXPECT_NE(pre.stderrText.find("absorbs and does not scatter"), std::string::npos) << pre.stderrText;
    const auto out = dir.path() / "jade.pfm";
    const auto render = test::runLucent("render " + model.string() +
                                        " --camera View --method ss --width 8 --height 8 -o " + out.string());
    ASSERT_EQ(render.exitCode, 0) << render.stderrText;
    EXPECT_EQ(readPfm(out).width, 8);
    const auto noCamera = test::runLucent("render " + model.string() + " --camera Side -o " + out.string());
    EXPECT_NE(noCamera.exitCode, 0);
    EXPECT_NE(noCamera.stderrText.find("jade.glb: has no camera named 'Side' (cameras: 'View')"), std::string::npos)
        << noCamera.stderrText;
    const auto sceneFile = dir.write("scene.json", scene((test::modelsDir() / "sphere.obj").string()));
    const auto named = test::runLucent("render " + sceneFile.string() + " --camera View -o " + out.string());
    EXPECT_NE(named.exitCode, 0);
    EXPECT_NE(named.stderrText.find("only glTF files hold several cameras"), std::string::npos) << named.stderrText;
}

// The same --seed gives byte-identical sample files and images for any --threads,
// through the command line, on a homogeneous sphere and on the torus cube (an
// opaque blocker inside).
TEST(Cli, SameSeedSameFilesForAnyThreadCount) {
    for (const char* model : {"sphere.json", "torus-cube.json"}) {
        test::ScratchDir dir;
        for (const std::string& file :
             {std::string(model), std::string("sphere.obj"), std::string("cube.obj"), std::string("torus.obj")})
            std::filesystem::copy_file(test::modelsDir() / file, dir.path() / file);
        const std::string sceneFile = (dir.path() / model).string();
        const std::string samples = (dir.path() / (std::filesystem::path(model).stem().string() + ".lsf")).string();
        std::vector<std::vector<char>> files;
        for (const char* threads : {"1", "2"}) {
            const auto run = test::runLucent("preprocess " + sceneFile +
                                             " --quality draft --samples 1500 --seed 9 --threads " + threads);
            ASSERT_EQ(run.exitCode, 0) << run.stderrText;
            std::ifstream in(samples, std::ios::binary);
            files.emplace_back((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
            const auto image = test::runLucent(
                "render " + sceneFile + " --method path --samples 2 --width 12 --height 12 --seed 3 --threads " +
                threads + " -o " + (dir.path() / (std::string(threads) + ".pfm")).string());
            ASSERT_EQ(image.exitCode, 0) << image.stderrText;
        }
        EXPECT_GT(files[0].size(), 1000u) << model;
        EXPECT_EQ(files[0], files[1]) << model;
        EXPECT_EQ(readPfm(dir.path() / "1.pfm").pixels, readPfm(dir.path() / "2.pfm").pixels) << model;
    }
}

// Without a usable EGL, the default backend falls back to OSMesa and says so.
TEST(Cli, FallsBackFromEglToOsmesa) {
    test::ScratchDir dir;
    const auto sceneFile = dir.write("scene.json", scene((test::modelsDir() / "sphere.obj").string()));
    ASSERT_EQ(test::runLucent("preprocess " + sceneFile.string() + " --quality draft --samples 300").exitCode, 0);
    const auto run = test::runLucent(
        "render " + sceneFile.string() + " -o " + (dir.path() / "a.pfm").string() + " --method ss --width 8 --height 8",
        "__EGL_VENDOR_LIBRARY_FILENAMES=/nonexistent.json");
    EXPECT_EQ(run.exitCode, 0) << run.stderrText;
    EXPECT_NE(run.stderrText.find("method ss on osmesa"), std::string::npos) << run.stderrText;
}

// OpenVDB binds 57 000 symbols when it is loaded (50 ms): only what builds or
// reads grids opens it (core/plugin_library.h). LD_DEBUG=files has the dynamic
// loader name every library it opens, preprocessing's showing that it would see
// OpenVDB were it loaded.
TEST(Cli, OnlyWhatNeedsOpenVdbLoadsIt) {
    test::ScratchDir dir;
    const auto sceneFile = dir.write("scene.json", scene((test::modelsDir() / "sphere.obj").string()));
    const auto preprocess =
        test::runLucent("preprocess " + sceneFile.string() + " --quality draft --samples 300", "LD_DEBUG=files");
    ASSERT_EQ(preprocess.exitCode, 0);
    EXPECT_NE(preprocess.stderrText.find("liblucent_preprocess_openvdb.so"), std::string::npos);
    EXPECT_NE(preprocess.stderrText.find("libopenvdb.so"), std::string::npos);
    const auto render = test::runLucent(
        "render " + sceneFile.string() + " -o " + (dir.path() / "a.png").string() + " --method ss --width 8 --height 8",
        "LD_DEBUG=files");
    ASSERT_EQ(render.exitCode, 0);
    EXPECT_EQ(render.stderrText.find("openvdb"), std::string::npos);
}

// libOSMesa links LLVM, 80-90 ms of a command's start (docs/architecture.md):
// it is opened only for an OSMesa context, and LLVM only for a context of
// either kind. The OSMesa render shows LD_DEBUG=files would see both.
TEST(Cli, OnlyAnOpenGlContextLoadsLlvm) {
    test::ScratchDir dir;
    const auto sceneFile = dir.write("scene.json", scene((test::modelsDir() / "sphere.obj").string()));
    ASSERT_EQ(test::runLucent("preprocess " + sceneFile.string() + " --quality draft --samples 300").exitCode, 0);
    const auto render = [&](const std::string& options) {
        return test::runLucent("render " + sceneFile.string() + " -o " + (dir.path() / "a.pfm").string() +
                                   " --width 8 --height 8 " + options,
                               "LD_DEBUG=files");
    };
    const auto osmesa = render("--method ss --backend osmesa");
    ASSERT_EQ(osmesa.exitCode, 0) << osmesa.stderrText;
    EXPECT_NE(osmesa.stderrText.find("libOSMesa.so"), std::string::npos);
    EXPECT_NE(osmesa.stderrText.find("libLLVM"), std::string::npos);
    const auto egl = render("--method ss --backend egl");
    ASSERT_EQ(egl.exitCode, 0) << egl.stderrText;
    EXPECT_EQ(egl.stderrText.find("libOSMesa"), std::string::npos);
    const auto reference = render("--method reference");
    ASSERT_EQ(reference.exitCode, 0) << reference.stderrText;
    EXPECT_EQ(reference.stderrText.find("libOSMesa"), std::string::npos);
    EXPECT_EQ(reference.stderrText.find("libLLVM"), std::string::npos);
}

// --scheme published writes the thesis's scheme, which info reports.
TEST(Cli, PublishedSchemeReachesTheSampleFile) {
    test::ScratchDir dir;
    const auto sceneFile = dir.write("scene.json", scene((test::modelsDir() / "sphere.obj").string()));
    ASSERT_EQ(test::runLucent("preprocess " + sceneFile.string() + " --quality draft --samples 300 --scheme published")
                  .exitCode,
              0);
    const auto info = test::runLucent("info " + (dir.path() / "out.lsf").string());
    EXPECT_NE(info.stdoutText.find("scheme                 published"), std::string::npos) << info.stdoutText;
    ASSERT_EQ(test::runLucent("preprocess " + sceneFile.string() + " --quality draft --samples 300").exitCode, 0);
    EXPECT_NE(
        test::runLucent("info " + (dir.path() / "out.lsf").string()).stdoutText.find("scheme                 lucent"),
        std::string::npos);
}

TEST(Cli, PreprocessThenInfo) {
    test::ScratchDir dir;
    const auto sceneFile = dir.write("scene.json", scene((test::modelsDir() / "sphere.obj").string()));
    const auto run = test::runLucent("preprocess " + sceneFile.string() + " --quality draft --samples 300");
    ASSERT_EQ(run.exitCode, 0) << run.stderrText;
    ASSERT_TRUE(std::filesystem::exists(dir.path() / "out.lsf"));
    const auto info = test::runLucent("info " + (dir.path() / "out.lsf").string());
    EXPECT_EQ(info.exitCode, 0) << info.stderrText;
    // A sphere of radius 1 is far more than 5.5 Poisson radii across: no Gaussian widens.
    EXPECT_NE(info.stdoutText.find("widened in thin parts  0 of"), std::string::npos) << info.stdoutText;
    const auto render = test::runLucent("render " + sceneFile.string() + " -o " + (dir.path() / "r.pfm").string() +
                                        " --width 8 --height 8 --method reference");
    EXPECT_EQ(render.exitCode, 0) << render.stderrText;
    EXPECT_TRUE(std::filesystem::exists(dir.path() / "r.pfm"));
}

// preprocess and info give the same layer count, also where the light reaches
// deeper than a thin plate's half thickness (fewer layers exist than depths fit).
TEST(Cli, PreprocessAndInfoAgreeOnTheLayerCount) {
    test::ScratchDir dir;
    const auto plate = test::writeBox(dir, "plate.obj", Vec3(-1, -1, -0.05), Vec3(1, 1, 0.05));
    const auto sceneFile = dir.write("scene.json", scene(plate.string(), R"("sigma_t": 0.5, "albedo": 0.5)"));
    const auto run = test::runLucent("preprocess " + sceneFile.string() + " --quality draft --samples 2000");
    ASSERT_EQ(run.exitCode, 0) << run.stderrText;
    const auto info = test::runLucent("info " + (dir.path() / "out.lsf").string());
    ASSERT_EQ(info.exitCode, 0) << info.stderrText;
    auto numberAfter = [](const std::string& text, const std::string& key) {
        const size_t at = text.find(key);
        return at == std::string::npos ? -1 : std::atoi(text.c_str() + at + key.size());
    };
    const int printed = numberAfter(run.stderrText, "plate.obj: ");
    const size_t infoAt = info.stdoutText.find("layers");
    ASSERT_NE(infoAt, std::string::npos) << info.stdoutText;
    const int recorded = std::atoi(info.stdoutText.c_str() + info.stdoutText.find_first_not_of(' ', infoAt + 6));
    EXPECT_GT(recorded, 0) << info.stdoutText;
    EXPECT_EQ(printed, recorded) << run.stderrText << info.stdoutText;
    // 0.1 thick is under 5.5 Poisson radii (docs/accuracy.md, Thin parts): every Gaussian whose nearest
    // boundary is a face of the plate widens. Those nearer a side may not: they lie within 0.05 of the rim,
    // (4 - 1.9^2) / 4 = 9.75% of the plate.
    const double radius = std::atof(info.stdoutText.c_str() + info.stdoutText.find("mean Poisson radius") + 19);
    ASSERT_GT(5.5 * radius, 0.1) << info.stdoutText;
    const int widened = numberAfter(info.stdoutText, "widened in thin parts  ");
    EXPECT_GE(widened, 0.9 * numberAfter(info.stdoutText, "samples")) << info.stdoutText;
    EXPECT_LE(widened, numberAfter(info.stdoutText, "samples")) << info.stdoutText;
}

}  // namespace
}  // namespace lucent

namespace lucent {
namespace {

// `lucent presets` lists every measured material with its published numbers, and
// a scene in centimetres that names one renders as the same scene given marble's
// coefficients per cm by hand (Jensen 2001: sigma_s' + sigma_a per mm, times 10).
TEST(Cli, PresetsAreListedAndAScaleInCentimetresRendersWithOne) {
    const auto list = test::runLucent("presets");
    ASSERT_EQ(list.exitCode, 0) << list.stderrText;
    EXPECT_EQ(std::count(list.stdoutText.begin(), list.stdoutText.end(), '\n'), 1 + 12 + 35);
    EXPECT_NE(list.stdoutText.find("marble"), std::string::npos);
    EXPECT_NE(list.stdoutText.find("2.19 2.62 3"), std::string::npos) << "marble's sigma_s'";
    EXPECT_NE(list.stdoutText.find("0.932 0.902 0.859"), std::string::npos) << "lowfat milk's g";

    test::ScratchDir dir;
    const std::string mesh = (test::modelsDir() / "sphere.obj").string();
    std::string preset = scene(mesh, R"("preset": "marble")");
    preset.insert(1, R"("units": "cm", )");
    const std::string byHand = scene(mesh, R"("sigma_t": [21.921, 26.241, 30.071],
        "albedo": [0.999042014506637, 0.998437559544225, 0.99763892121978])");
    auto render = [&](const std::string& name, const std::string& text) {
        const auto file = dir.write(name + ".json", text);
        const auto run = test::runLucent("render " + file.string() + " -o " + (dir.path() / (name + ".pfm")).string() +
                                         " --method reference --width 8 --height 8");
        EXPECT_EQ(run.exitCode, 0) << run.stderrText;
        return readPfm(dir.path() / (name + ".pfm"));
    };
    const Image a = render("preset", preset), b = render("by-hand", byHand);
    ASSERT_EQ(a.pixels.size(), b.pixels.size());
    double sum = 0.0;
    for (size_t i = 0; i < a.pixels.size(); ++i) {
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(a.pixels[i][c], b.pixels[i][c], 1e-5 * b.pixels[i][c]) << i;
        sum += b.pixels[i].r;
    }
    EXPECT_GT(sum, 0.0);
}

}  // namespace
}  // namespace lucent
