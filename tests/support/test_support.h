#pragma once
// Helpers shared by the test suites: a scratch directory per test, small files,
// and running the lucent binary.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/scene.h"
#include "core/triangle_mesh.h"

namespace lucent::test {

// The message of the Error f throws (fails the test if it throws none).
template <class F>
std::string errorOf(F&& f) {
    try {
        f();
    } catch (const Error& e) {
        return e.what();
    }
    ADD_FAILURE() << "no error";
    return {};
}

#define EXPECT_CONTAINS(text, part) EXPECT_NE(std::string(text).find(part), std::string::npos) << (text)

// A fresh directory under the system temp dir, removed when the object dies.
class ScratchDir {
public:
    ScratchDir();
    ~ScratchDir();
    const std::filesystem::path& path() const { return path_; }
    std::filesystem::path write(const std::string& name, const std::string& contents) const;

private:
    std::filesystem::path path_;
};

std::filesystem::path sourceDir();
std::filesystem::path modelsDir();
std::filesystem::path dataDir();

// An axis-aligned box [lo, hi] as an OBJ file in dir (outward faces).
std::filesystem::path writeBox(const ScratchDir& dir, const std::string& name, const Vec3& lo, const Vec3& hi);

// What most scenes of the tests hold: a square image from a camera looking at
// target, and point lights (power: W/sr per channel).
Camera squareCamera(const Vec3& position, const Vec3& target, double fovYDegrees, int size);
Light pointLight(const Vec3& position, const Rgb& power);

// The ObjectDesc for a mesh with a constant medium, fingerprint left 0.
ObjectDesc simpleObject(const std::filesystem::path& mesh, double sigmaT, double albedo = 0.5);

// Runs build/bin/lucent with args; captures the exit code, stderr and stdout.
struct RunResult {
    int exitCode;
    std::string stderrText;
    std::string stdoutText;
};
RunResult runLucent(const std::string& args, const std::string& environment = "");

// A PNG decoded by libpng (its simplified API) to 8-bit RGB, rows from the top;
// width 0 when it cannot be read.
struct Png {
    int width = 0, height = 0;
    std::vector<unsigned char> rgb;
    const unsigned char* at(int x, int y) const { return &rgb[(size_t(y) * width + x) * 3]; }
};
Png readPng(const std::filesystem::path& file);

// The error parsing a scene text as "dir/scene.json" gives, or "no error".
std::string sceneErrorOf(const std::string& text);

// Parses a CSV file, skipping lines starting with '#' and the header line.
std::vector<std::vector<std::string>> readCsv(const std::filesystem::path& file);

}  // namespace lucent::test
