#include "bench/cgal_demo_meshes.h"

#include <zlib.h>

#include <algorithm>
#include <cstring>
#include <fstream>
#include <memory>
#include <sstream>
#include <vector>

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/input_file.h"
#include "core/triangle_mesh.h"

namespace lucent {
namespace {

constexpr uint64_t kMaxMeshBytes = uint64_t(256) << 20;  // the largest demo mesh is a few MB

struct GzFile {
    gzFile file;
    ~GzFile() {
        if (file) gzclose(file);
    }
};

// Reads exactly n bytes (false at the archive's end).
bool readBlock(gzFile in, char* out, size_t n) { return gzread(in, out, unsigned(n)) == int(n); }

}  // namespace

std::filesystem::path extractCgalDemoMesh(const std::string& name, const std::filesystem::path& dir,
                                          const std::filesystem::path& archive) {
    if (name.empty() || name.size() > 64 ||
        name.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789-_") != std::string::npos)
        throw Error("CGAL demo mesh '" + name + "': a name is letters, digits, '-' and '_' (for example elephant)");
    regularFileSize(archive, "CGAL demo archive (install the Debian package libcgal-demo)");
    GzFile in{gzopen(archive.c_str(), "rb")};
    if (!in.file) throw Error(archive.string(), "cannot open the CGAL demo archive");
    const std::string wanted = "data/meshes/" + name + ".off";
    char header[512];
    while (readBlock(in.file, header, sizeof header)) {
        if (header[0] == '\0') break;  // the end-of-archive blocks
        // ustar: name [0, 100), size in octal [124, 136), prefix [345, 500).
        std::string path(header, strnlen(header, 100));
        if (std::memcmp(header + 257, "ustar", 5) == 0 && header[345] != '\0')
            path = std::string(header + 345, strnlen(header + 345, 155)) + "/" + path;
        const std::string sizeField(header + 124, strnlen(header + 124, 12));
        uint64_t size = 0;
        for (char c : sizeField) {
            if (c == ' ') continue;
            if (c < '0' || c > '7') throw Error(archive.string(), "malformed tar header (size of " + path + ")");
            size = size * 8 + uint64_t(c - '0');
            if (size > (uint64_t(1) << 40))
                throw Error(archive.string(), "malformed tar header (size of " + path + ")");
        }
        const uint64_t padded = (size + 511) / 512 * 512;
        if (path == wanted) {
            if (size > kMaxMeshBytes) throw Error(archive.string(), wanted + " is larger than 256 MiB");
            std::vector<char> bytes(padded);
            if (!readBlock(in.file, bytes.data(), bytes.size()))
                throw Error(archive.string(), "the archive ends inside " + wanted);
            std::filesystem::create_directories(dir);
            const std::filesystem::path out = dir / (name + ".off");
            AtomicFile file(out);
            file.stream().write(bytes.data(), std::streamsize(size));
            file.commit();
            return out;
        }
        std::vector<char> skip(std::min<uint64_t>(padded, 1 << 20));
        for (uint64_t left = padded; left > 0;) {
            const size_t n = size_t(std::min<uint64_t>(left, skip.size()));
            if (!readBlock(in.file, skip.data(), n)) throw Error(archive.string(), "the archive ends inside " + path);
            left -= n;
        }
    }
    throw Error(archive.string(), "holds no mesh '" + name + "' (" + wanted + ")");
}

std::filesystem::path writeMeshScene(const std::filesystem::path& mesh, const std::filesystem::path& dir,
                                     double opticalRadius, int size) {
    std::vector<std::string> warnings;
    const Bounds3 box = loadClosedMesh(mesh, warnings).bounds();
    const Vec3 centre = box.center(), half = 0.5 * box.extent();
    const double diagonal = box.diagonal();
    const Vec3 eye = centre + 2.2 * diagonal * glm::normalize(Vec3(0.35, 0.3, 1.0));
    const Vec3 light = centre + 1.5 * diagonal * glm::normalize(Vec3(1.0, 1.2, 0.8));
    const double sigmaT = opticalRadius / std::min({half.x, half.y, half.z});
    auto vec = [](const Vec3& v) {
        std::ostringstream s;
        s.precision(17);
        s << "[" << v.x << ", " << v.y << ", " << v.z << "]";
        return s.str();
    };
    std::ostringstream json;
    json.precision(17);
    json << "{\"camera\": {\"position\": " << vec(eye) << ", \"target\": " << vec(centre)
         << ", \"fov_y\": 30, \"width\": " << size << ", \"height\": " << size << "},\n"
         << " \"lights\": [{\"type\": \"point\", \"position\": " << vec(light)
         << ", \"intensity\": " << 10.0 * diagonal * diagonal << "}],\n"
         << " \"objects\": [{\"mesh\": \"" << mesh.filename().string() << "\", \"medium\": {\"sigma_t\": " << sigmaT
         << ", \"albedo\": 0.8}, \"samples\": \"" << mesh.stem().string() << ".lsf\"}]}\n";
    const std::filesystem::path out = dir / (mesh.stem().string() + ".json");
    AtomicFile file(out);
    file.stream() << json.str();
    file.commit();
    return out;
}

}  // namespace lucent
