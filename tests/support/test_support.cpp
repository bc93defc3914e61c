#include "tests/support/test_support.h"

#include <png.h>

#include "core/error.h"

#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <random>
#include <sstream>

namespace lucent::test {

ScratchDir::ScratchDir() {
    std::random_device rd;
    path_ = std::filesystem::temp_directory_path() /
            ("lucent-test-" + std::to_string(::getpid()) + "-" + std::to_string(rd()));
    std::filesystem::create_directories(path_);
}

ScratchDir::~ScratchDir() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
}

std::filesystem::path ScratchDir::write(const std::string& name, const std::string& contents) const {
    const auto file = path_ / name;
    std::ofstream(file, std::ios::binary) << contents;
    return file;
}

std::filesystem::path sourceDir() { return LUCENT_SOURCE_DIR; }
std::filesystem::path modelsDir() { return sourceDir() / "models"; }
std::filesystem::path dataDir() { return sourceDir() / "tests" / "data"; }

std::filesystem::path writeBox(const ScratchDir& dir, const std::string& name, const Vec3& lo, const Vec3& hi) {
    std::string obj;
    for (int k = 0; k < 8; ++k) {
        const Vec3 v(k & 1 ? hi.x : lo.x, k & 2 ? hi.y : lo.y, k & 4 ? hi.z : lo.z);
        char line[128];
        std::snprintf(line, sizeof line, "v %.17g %.17g %.17g\n", v.x, v.y, v.z);
        obj += line;
    }
    obj +=
        "f 1 3 4\nf 1 4 2\nf 5 6 8\nf 5 8 7\nf 1 2 6\nf 1 6 5\nf 3 7 8\nf 3 8 4\nf 1 5 7\nf 1 7 3\nf 2 4 8\nf 2 8 6\n";
    return dir.write(name, obj);
}

Camera squareCamera(const Vec3& position, const Vec3& target, double fovYDegrees, int size) {
    Camera c;
    c.position = position;
    c.target = target;
    c.fovYDegrees = fovYDegrees;
    c.width = c.height = size;
    return c;
}

Light pointLight(const Vec3& position, const Rgb& power) {
    Light l;
    l.position = position;
    l.power = power;
    return l;
}

ObjectDesc simpleObject(const std::filesystem::path& mesh, double sigmaT, double albedo) {
    ObjectDesc o;
    o.name = mesh.filename().string();
    o.mesh = mesh;
    o.medium.sigmaT = Rgb(sigmaT);
    o.medium.albedo = Rgb(albedo);
    o.samples = "unused.lsf";
    return o;
}

RunResult runLucent(const std::string& args, const std::string& environment) {
    ScratchDir scratch;
    const auto errFile = scratch.path() / "stderr.txt", outFile = scratch.path() / "stdout.txt";
    const std::string command = environment + " " + std::string(LUCENT_BINARY) + " " + args + " > " + outFile.string() +
                                " 2> " + errFile.string();
    const int status = std::system(command.c_str());
    auto read = [](const std::filesystem::path& file) {
        std::ifstream in(file);
        std::stringstream text;
        text << in.rdbuf();
        return text.str();
    };
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, read(errFile), read(outFile)};
}

std::vector<std::vector<std::string>> readCsv(const std::filesystem::path& file) {
    std::ifstream in(file);
    std::vector<std::vector<std::string>> rows;
    std::string line;
    bool header = true;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') continue;
        if (header) {
            header = false;
            continue;
        }
        std::vector<std::string> cells;
        std::stringstream ss(line);
        std::string cell;
        while (std::getline(ss, cell, ',')) cells.push_back(cell);
        if (!line.empty() && line.back() == ',') cells.emplace_back();
        rows.push_back(cells);
    }
    return rows;
}

Png readPng(const std::filesystem::path& file) {
    Png out;
    png_image png{};
    png.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_file(&png, file.c_str())) return out;
    png.format = PNG_FORMAT_RGB;
    out.rgb.resize(PNG_IMAGE_SIZE(png));
    if (!png_image_finish_read(&png, nullptr, out.rgb.data(), 0, nullptr)) return Png{};
    out.width = int(png.width);
    out.height = int(png.height);
    return out;
}

std::string sceneErrorOf(const std::string& text) {
    try {
        parseSceneText(text, "dir/scene.json");
    } catch (const Error& e) {
        return e.what();
    }
    return "no error";
}

}  // namespace lucent::test
