#include "bench/cycles_peer.h"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>

#include <nlohmann/json.hpp>

#include "core/error.h"
#include "core/run_program.h"

namespace lucent {

namespace {

void writeObj(const std::filesystem::path& file, const TriangleMesh& mesh) {
    std::ofstream out(file);
    out.precision(9);
    for (const Vec3& p : mesh.positions) out << "v " << p.x << ' ' << p.y << ' ' << p.z << '\n';
    for (const auto& t : mesh.triangles) out << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
    if (!out) throw Error(file.string(), "cannot write");
}

nlohmann::json json3(const Vec3& v) { return {v.x, v.y, v.z}; }

// What render_scene.py reads (its header says the format). Written by a JSON
// library: a path may hold quotes or backslashes.
void writeSpec(const std::filesystem::path& file, const std::filesystem::path& dir, const CyclesScene& scene,
               const std::vector<CyclesRender>& renders) {
    const Camera& c = scene.camera;
    const MediumDesc& m = scene.medium;
    const Rgb sigmaS = m.sigmaT * m.albedo, sigmaA = m.sigmaT - sigmaS;
    nlohmann::json spec = {{"mesh", (dir / "mesh.obj").string()},
                           {"camera",
                            {{"position", json3(c.position)},
                             {"target", json3(c.target)},
                             {"up", json3(c.up)},
                             {"fov_y", c.fovYDegrees},
                             {"width", c.width},
                             {"height", c.height}}},
                           {"lights", nlohmann::json::array()},
                           {"medium", {{"sigma_s", json3(Vec3(sigmaS))}, {"sigma_a", json3(Vec3(sigmaA))}, {"g", m.g}}},
                           {"volume_bounces", scene.volumeBounces},
                           {"renders", nlohmann::json::array()},
                           {"threads", 2},
                           {"output", dir.string()}};
    for (const Light& l : scene.lights) {
        if (l.type != Light::Type::Point || l.spot || l.radius != 0.0)
            throw Error(file.string(), "the Cycles peer takes point lights only");
        spec["lights"].push_back({{"position", json3(l.position)}, {"intensity", json3(Vec3(l.power))}});
    }
    for (const CyclesRender& r : renders)
        spec["renders"].push_back({{"name", r.name}, {"samples", r.samples}, {"seed", r.seed}});
    std::ofstream out(file);
    out << spec.dump(1) << '\n';
    if (!out) throw Error(file.string(), "cannot write");
}

// cycles-times.csv: a header, then "name,seconds" per render.
std::map<std::string, double> readTimes(const std::filesystem::path& file) {
    std::ifstream in(file);
    if (!in) throw Error(file.string(), "Cycles wrote no times");
    std::map<std::string, double> times;
    std::string line;
    std::getline(in, line);
    while (std::getline(in, line)) {
        const size_t comma = line.find(',');
        char* end = nullptr;
        const double seconds = comma == std::string::npos ? 0.0 : std::strtod(line.c_str() + comma + 1, &end);
        if (comma == std::string::npos || end == line.c_str() + comma + 1 || !(seconds >= 0.0))
            throw Error(file.string(), "bad line: " + line);
        times[line.substr(0, comma)] = seconds;
    }
    return times;
}

}  // namespace

std::vector<CyclesImage> renderWithCycles(const std::string& blender, const std::filesystem::path& dir,
                                          const CyclesScene& scene, const std::vector<CyclesRender>& renders) {
    std::filesystem::create_directories(dir);
    writeObj(dir / "mesh.obj", scene.mesh);
    writeSpec(dir / "peer-scene.json", dir, scene, renders);
    const std::filesystem::path script = std::filesystem::path(LUCENT_SOURCE_DIR) / "bench/cycles/render_scene.py";
    const std::filesystem::path log = dir / "blender.log";
    std::fprintf(stderr, "running Cycles (%s) for %zu renders, its output in %s...\n", blender.c_str(), renders.size(),
                 log.c_str());
    const int status = runProgram({blender, "-b", "--factory-startup", "-noaudio", "--python-exit-code", "1",
                                   "--python", script.string(), "--", (dir / "peer-scene.json").string()},
                                  log);
    if (status != 0)
        throw Error(blender, "Cycles' render failed (exit " + std::to_string(status) + "; see " + log.string() + ")");
    const std::map<std::string, double> times = readTimes(dir / "cycles-times.csv");
    std::vector<CyclesImage> out;
    for (const CyclesRender& r : renders) {
        const auto t = times.find(r.name);
        if (t == times.end()) throw Error((dir / "cycles-times.csv").string(), "no time for render " + r.name);
        out.push_back({r, t->second, readPfm(dir / ("cycles-" + r.name + ".pfm"))});
    }
    return out;
}

}  // namespace lucent
