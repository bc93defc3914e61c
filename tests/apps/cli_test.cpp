// The lucent command on bad input: one "lucent: error:" line naming the file and
// the problem, a non-zero exit, and no output file left behind.
#include <gtest/gtest.h>

#include <fstream>

#include "tests/support/test_support.h"

namespace lucent {
namespace {

const char* kTetra = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";

std::string scene(const std::string& mesh, const std::string& medium = R"("sigma_t": 2, "albedo": 0.5)") {
    return R"({"camera": {"position": [0, 0, 5], "target": [0, 0, 0], "fov_y": 40, "width": 16, "height": 16},
               "lights": [{"type": "point", "position": [3, 3, 3], "intensity": 10}],
               "objects": [{"mesh": ")" + mesh + R"(", "medium": {)" + medium + R"(}, "samples": "out.lsf"}]})";
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
    text.insert(text.rfind('}'), R"(, "render": {"method": "lbl"})");
    expectFailure("render " + dir.write("scene.json", text).string() + " -o " + (dir.path() / "img.png").string(),
                  "scene.json: /render/method: method 'lbl' is not built into this binary (built: ss, reference, auto)",
                  "img.png");
}

TEST(Cli, HelpOffersOnlyTheMethodsThisBuildHas) {
    const auto help = test::runLucent("render --help");
    ASSERT_EQ(help.exitCode, 0) << help.stderrText;
    EXPECT_NE(help.stdoutText.find("--method TEXT:{ss,reference,auto}"), std::string::npos) << help.stdoutText;
    for (const char* absent : {"lbl", "mdom", "path:"})
        EXPECT_EQ(help.stdoutText.find(absent), std::string::npos) << absent;
}

TEST(Cli, AutoSaysWhatItChoseAndWhy) {
    test::ScratchDir dir;
    const auto sceneFile = dir.write("scene.json", scene((test::modelsDir() / "sphere.obj").string()));
    ASSERT_EQ(test::runLucent("preprocess " + sceneFile.string() + " --quality draft --samples 300").exitCode, 0);
    const auto run = test::runLucent("render " + sceneFile.string() + " -o " + (dir.path() / "a.pfm").string() +
                                     " --method auto --width 8 --height 8");
    ASSERT_EQ(run.exitCode, 0) << run.stderrText;
    EXPECT_NE(run.stderrText.find("method ss on "), std::string::npos) << run.stderrText;
    EXPECT_NE(run.stderrText.find(", chosen by auto: the only interactive method built)"), std::string::npos)
        << run.stderrText;
}

TEST(Cli, PreprocessThenInfo) {
    test::ScratchDir dir;
    const auto sceneFile = dir.write("scene.json", scene((test::modelsDir() / "sphere.obj").string()));
    const auto run = test::runLucent("preprocess " + sceneFile.string() + " --quality draft --samples 300");
    ASSERT_EQ(run.exitCode, 0) << run.stderrText;
    ASSERT_TRUE(std::filesystem::exists(dir.path() / "out.lsf"));
    const auto info = test::runLucent("info " + (dir.path() / "out.lsf").string());
    EXPECT_EQ(info.exitCode, 0) << info.stderrText;
    const auto render = test::runLucent("render " + sceneFile.string() + " -o " + (dir.path() / "r.pfm").string() +
                                        " --width 8 --height 8 --method reference");
    EXPECT_EQ(render.exitCode, 0) << render.stderrText;
    EXPECT_TRUE(std::filesystem::exists(dir.path() / "r.pfm"));
}

}  // namespace
}  // namespace lucent
