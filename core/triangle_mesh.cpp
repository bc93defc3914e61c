#include "core/triangle_mesh.h"

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/System/omstream.hh>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iostream>
#include <sstream>

#include "core/error.h"
#include "core/input_file.h"
#include "core/limits.h"
#include "core/mesh_file_check.h"

namespace lucent {

Bounds3 TriangleMesh::bounds() const {
    Bounds3 b;
    for (const Vec3& p : positions) b.extend(p);
    return b;
}

Vec3 TriangleMesh::faceNormal(size_t face) const {
    const auto& t = triangles[face];
    return glm::cross(positions[t[1]] - positions[t[0]], positions[t[2]] - positions[t[0]]);
}

std::vector<std::array<Vec3, 3>> cornerNormals(const TriangleMesh& mesh) {
    const size_t faces = mesh.triangles.size();
    // Each face's normal scaled by twice its area (what the corners sum), and its direction.
    std::vector<Vec3> weighted(faces), unit(faces);
    for (size_t f = 0; f < faces; ++f) {
        weighted[f] = mesh.faceNormal(f);
        const double length = glm::length(weighted[f]);
        unit[f] = length > 0.0 ? weighted[f] / length : Vec3(0.0);
    }
    // The faces around each vertex, in compressed rows.
    std::vector<uint32_t> start(mesh.positions.size() + 1, 0), around(3 * faces);
    for (const auto& t : mesh.triangles)
        for (uint32_t v : t) ++start[v + 1];
    for (size_t v = 0; v < mesh.positions.size(); ++v) start[v + 1] += start[v];
    std::vector<uint32_t> fill(start.begin(), start.end() - 1);
    for (size_t f = 0; f < faces; ++f)
        for (uint32_t v : mesh.triangles[f]) around[fill[v]++] = uint32_t(f);

    const double cosCrease = std::cos(kCreaseDegrees * kPi / 180.0);
    std::vector<std::array<Vec3, 3>> corners(faces);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, faces, 4096), [&](const tbb::blocked_range<size_t>& range) {
        for (size_t f = range.begin(); f != range.end(); ++f)
            for (int c = 0; c < 3; ++c) {
                const uint32_t v = mesh.triangles[f][c];
                Vec3 sum(0.0);
                for (uint32_t i = start[v]; i < start[v + 1]; ++i)
                    if (glm::dot(unit[around[i]], unit[f]) >= cosCrease) sum += weighted[around[i]];
                const double length = glm::length(sum);
                corners[f][c] = length > 0.0 ? sum / length : unit[f];
            }
    });
    return corners;
}

Vec3 interpolatedNormal(const TriangleMesh& mesh, const std::array<Vec3, 3>& corners, size_t face, const Vec3& p) {
    const auto& t = mesh.triangles[face];
    const Vec3 a = mesh.positions[t[0]], e1 = mesh.positions[t[1]] - a, e2 = mesh.positions[t[2]] - a;
    const Vec3 n = glm::cross(e1, e2);
    const double area2 = glm::dot(n, n);
    if (!(area2 > 0.0)) return corners[0];
    // Barycentric coordinates of p projected onto the face's plane.
    const Vec3 d = p - a;
    const double b1 = glm::dot(glm::cross(d, e2), n) / area2, b2 = glm::dot(glm::cross(e1, d), n) / area2;
    const Vec3 sum = (1.0 - b1 - b2) * corners[0] + b1 * corners[1] + b2 * corners[2];
    const double length = glm::length(sum);
    return length > 0.0 ? sum / length : glm::normalize(n);
}

double TriangleMesh::signedVolume() const {
    // Divergence theorem: sum of signed tetrahedra against the bounding-box centre
    // (a nearby origin keeps the cancellation error small for meshes far from 0).
    const Vec3 o = bounds().center();
    double v = 0.0;
    for (const auto& t : triangles)
        v += glm::dot(positions[t[0]] - o, glm::cross(positions[t[1]] - o, positions[t[2]] - o));
    return v / 6.0;
}

double TriangleMesh::area() const {
    double a = 0.0;
    for (size_t f = 0; f < triangles.size(); ++f) a += 0.5 * glm::length(faceNormal(f));
    return a;
}

namespace {

using OmMesh = OpenMesh::TriMesh_ArrayKernelT<>;

// OpenMesh reports faces it refuses (non-manifold "complex edge"/"complex vertex")
// only on its error stream, so Lucent takes that stream over: connected once for
// the whole process, because OpenMesh's disconnect() leaks what connect() allocates.
class OpenMeshErrorCapture {
public:
    static OpenMeshErrorCapture& instance() {
        static OpenMeshErrorCapture capture;
        return capture;
    }
    void clear() {
        ::omerr().flush();
        text_.str({});
        sink_.str({});
    }
    std::string text() {
        ::omerr().flush();
        return text_.str();
    }

private:
    OpenMeshErrorCapture() {
        ::omerr().disconnect(std::cerr);
        ::omerr().connect(text_);
        // Its log and output streams too: a reader's remarks ("Unsupported entry
        // type") are not the user's business; Lucent says what is wrong in one line.
        ::omlog().disconnect(std::clog);
        ::omlog().disconnect(std::cerr);
        ::omout().disconnect(std::cout);
        ::omlog().connect(sink_);
        ::omout().connect(sink_);
    }
    std::ostringstream text_;
    std::ostringstream sink_;  // grows by what OpenMesh remarks; cleared with text_
};

// Sends file descriptor 2 to /dev/null while it lives.
class SilencedStandardError {
public:
    SilencedStandardError() {
        std::cerr.flush();
        saved_ = ::dup(STDERR_FILENO);
        const int devNull = ::open("/dev/null", O_WRONLY);
        if (devNull >= 0) {
            ::dup2(devNull, STDERR_FILENO);
            ::close(devNull);
        }
    }
    ~SilencedStandardError() {
        std::cerr.flush();
        if (saved_ >= 0) {
            ::dup2(saved_, STDERR_FILENO);
            ::close(saved_);
        }
    }
    SilencedStandardError(const SilencedStandardError&) = delete;
    SilencedStandardError& operator=(const SilencedStandardError&) = delete;

private:
    int saved_ = -1;
};

TriangleMesh checkedClosedMesh(OmMesh& om, const std::string& openMeshErrors, const std::string& file,
                               std::vector<std::string>& warnings);

// OpenMesh's STL reader drops vertices that are not finite, and the faces using
// them, without a word; look at binary STL coordinates ourselves first.
void rejectNonFiniteBinaryStl(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary | std::ios::ate);
    const auto size = static_cast<uint64_t>(in.tellg());
    if (size < 84) return;
    in.seekg(80);
    uint32_t count = 0;
    in.read(reinterpret_cast<char*>(&count), 4);
    if (size != 84 + 50ull * count) return;  // ASCII STL: OpenMesh reports what it cannot parse
    char record[50];
    for (uint32_t f = 0; f < count && in.read(record, 50); ++f)
        for (int k = 3; k < 12; ++k) {
            float v;
            std::memcpy(&v, record + 4 * k, 4);
            if (!std::isfinite(v))
                throw Error(path.string(), "triangle " + std::to_string(f) + " has a non-finite coordinate");
        }
}

}  // namespace

TriangleMesh loadClosedMesh(const std::filesystem::path& path, std::vector<std::string>& warnings) {
    const std::string file = path.string();
    const uint64_t size = regularFileSize(path, "mesh file");
    std::string extension = path.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(), ::tolower);
    if (extension != ".obj" && extension != ".off" && extension != ".ply" && extension != ".stl")
        throw Error(file, "unsupported mesh format '" + extension + "' (use .obj, .off, .ply or .stl)");
    checkMeshFileClaims(path, extension, size);
    if (extension == ".stl") rejectNonFiniteBinaryStl(path);
    OpenMeshErrorCapture& capture = OpenMeshErrorCapture::instance();
    OmMesh om;
    capture.clear();
    OpenMesh::IO::Options options;
    // OpenMesh reserves what a file claims; a corrupt count can ask for more than
    // there is (found by fuzz/mesh_fuzzer.cpp in files the header checks let pass).
    bool read = false;
    try {
        // Some of OpenMesh's readers remark on std::cerr ("Unsupported entry type")
        // past its error stream; what is wrong reaches the user in Lucent's one line.
        const SilencedStandardError silence;
        read = OpenMesh::IO::read_mesh(om, file, options);
    } catch (const std::bad_alloc&) {
        throw Error(file, "malformed mesh file (reading it asked for more memory than there is: a corrupt count?)");
    } catch (const std::exception& e) {
        throw Error(file, std::string("malformed mesh file (") + e.what() + ")");
    }
    if (!read) throw Error(file, "cannot read mesh (unsupported format or malformed file)");
    const std::string openMeshErrors = capture.text();
    // OpenMesh skips a vertex line it cannot parse ("nan", "inf", garbage) and then
    // every face that uses it, reporting only the faces.
    if (openMeshErrors.find("invalid vertex index") != std::string::npos)
        throw Error(
            file,
            "a vertex has non-finite or malformed coordinates (a face refers to a vertex that could not be read)");
    return checkedClosedMesh(om, openMeshErrors, file, warnings);
}

TriangleMesh closedMesh(const std::vector<Vec3>& positions, const std::vector<std::array<uint32_t, 3>>& triangles,
                        const std::string& name, std::vector<std::string>& warnings) {
    OmMesh om;
    for (const Vec3& p : positions) om.add_vertex(OmMesh::Point(float(p.x), float(p.y), float(p.z)));
    OpenMeshErrorCapture& capture = OpenMeshErrorCapture::instance();
    capture.clear();
    for (size_t f = 0; f < triangles.size(); ++f) {
        const auto& t = triangles[f];
        for (uint32_t v : t)
            if (v >= positions.size())
                throw Error(name, "triangle " + std::to_string(f) + " refers to vertex " + std::to_string(v) + " of " +
                                      std::to_string(positions.size()));
        om.add_face(OmMesh::VertexHandle(int(t[0])), OmMesh::VertexHandle(int(t[1])), OmMesh::VertexHandle(int(t[2])));
    }
    return checkedClosedMesh(om, capture.text(), name, warnings);
}

namespace {

// What every closed mesh must be, however it was read: the checks of
// loadClosedMesh after OpenMesh holds it (errors: what OpenMesh reported).
TriangleMesh checkedClosedMesh(OmMesh& om, const std::string& openMeshErrors, const std::string& file,
                               std::vector<std::string>& warnings) {
    if (openMeshErrors.find("complex") != std::string::npos)
        throw Error(file, "mesh is not manifold (an edge or vertex is shared by more than two face fans)");
    if (om.n_faces() == 0 || om.n_vertices() == 0) throw Error(file, "mesh is empty");

    TriangleMesh mesh;
    mesh.positions.reserve(om.n_vertices());
    for (auto v : om.vertices()) {
        const auto p = om.point(v);
        const Vec3 q(p[0], p[1], p[2]);
        if (!isFinite(q)) throw Error(file, "vertex " + std::to_string(v.idx()) + " has a non-finite coordinate");
        if (std::max({std::abs(q.x), std::abs(q.y), std::abs(q.z)}) > kMaxCoordinate)
            throw Error(file, "vertex " + std::to_string(v.idx()) +
                                  " lies farther than 1e13 from the origin, "
                                  "beyond the single-precision range Lucent renders (docs/robustness.md)");
        mesh.positions.push_back(q);
    }
    for (auto e : om.edges())
        if (om.is_boundary(e))
            throw Error(file, "mesh is not closed (edge between vertices " +
                                  std::to_string(om.from_vertex_handle(om.halfedge_handle(e, 0)).idx()) + " and " +
                                  std::to_string(om.to_vertex_handle(om.halfedge_handle(e, 0)).idx()) +
                                  " borders a hole)");
    for (auto v : om.vertices()) {
        if (om.is_isolated(v)) continue;
        if (!om.is_manifold(v)) throw Error(file, "mesh is not manifold at vertex " + std::to_string(v.idx()));
    }

    if (!(mesh.bounds().diagonal() >= kMinObjectSize)) {
        char size[32];
        std::snprintf(size, sizeof size, "%.3g", mesh.bounds().diagonal());
        throw Error(file, std::string("mesh is ") + size +
                              " across; Lucent renders objects at least 1e-9 across "
                              "(scale the scene's units; docs/robustness.md)");
    }
    size_t degenerate = 0;
    const double scale = std::max(mesh.bounds().diagonal(), 1e-300);
    for (auto f : om.faces()) {
        std::array<uint32_t, 3> tri;
        int k = 0;
        for (auto v : om.fv_range(f)) tri[k++] = uint32_t(v.idx());
        const Vec3 n = glm::cross(mesh.positions[tri[1]] - mesh.positions[tri[0]],
                                  mesh.positions[tri[2]] - mesh.positions[tri[0]]);
        // Relative to the model's size so that tiny and huge models behave alike.
        if (glm::length(n) <= 1e-14 * scale * scale) {
            ++degenerate;
            continue;
        }
        mesh.triangles.push_back(tri);
    }
    if (mesh.triangles.empty()) throw Error(file, "mesh is empty (every face has zero area)");
    if (degenerate > 0) warnings.push_back(file + ": removed " + std::to_string(degenerate) + " zero-area face(s)");

    const double volume = mesh.signedVolume();
    if (!(std::abs(volume) > 0.0)) throw Error(file, "mesh encloses no volume");
    if (volume < 0.0) {
        for (auto& t : mesh.triangles) std::swap(t[1], t[2]);
        warnings.push_back(file + ": faces pointed inwards; orientation flipped");
    }
    return mesh;
}

}  // namespace

}  // namespace lucent
