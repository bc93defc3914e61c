#include "tests/support/test_support.h"

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
    const std::string command = environment + " " + std::string(LUCENT_BINARY) + " " + args + " > " +
                                outFile.string() + " 2> " + errFile.string();
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
        if (header) { header = false; continue; }
        std::vector<std::string> cells;
        std::stringstream ss(line);
        std::string cell;
        while (std::getline(ss, cell, ',')) cells.push_back(cell);
        if (!line.empty() && line.back() == ',') cells.emplace_back();
        rows.push_back(cells);
    }
    return rows;
}

}  // namespace lucent::test
