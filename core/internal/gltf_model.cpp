#include "core/internal/gltf_model.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <map>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>
#include <set>
#include <tuple>

#include "core/error.h"
#include "core/input_file.h"

namespace lucent::gltf {
namespace {

namespace fs = std::filesystem;

bool isBinary(const fs::path& file) {
    std::string ext = file.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return ext == ".glb";
}

std::string readBytes(const fs::path& file, const std::string& what) {
    return readTextFile(file, what, kMemoryBudgetBytes);
}

uint32_t le32(const std::string& bytes, size_t at) {
    uint32_t v = 0;
    for (int i = 3; i >= 0; --i) v = (v << 8) | uint8_t(bytes[at + size_t(i)]);
    return v;
}

// The JSON chunk of a .glb after checking its header and chunk lengths against
// the file (glTF 2.0, section 4.4: magic, version 2, length, then chunks).
std::string glbJson(const std::string& bytes, const std::string& file, uint64_t& binBytes) {
    if (bytes.size() < 20 || bytes.compare(0, 4, "glTF") != 0)
        throw Error(file, "not a binary glTF file (no 'glTF' header)");
    if (le32(bytes, 4) != 2)
        throw Error(file, "binary glTF version " + std::to_string(le32(bytes, 4)) + "; only 2 is read");
    if (le32(bytes, 8) != bytes.size())
        throw Error(file, "header says " + std::to_string(le32(bytes, 8)) + " bytes, the file has " +
                              std::to_string(bytes.size()));
    const uint64_t jsonBytes = le32(bytes, 12);
    if (le32(bytes, 16) != 0x4E4F534Au || 20 + jsonBytes > bytes.size())
        throw Error(file, "the first chunk is not a JSON chunk inside the file");
    binBytes = 0;
    const uint64_t next = 20 + ((jsonBytes + 3) / 4) * 4;
    if (next + 8 <= bytes.size()) {
        binBytes = le32(bytes, size_t(next));
        if (next + 8 + binBytes > bytes.size()) throw Error(file, "the binary chunk runs past the end of the file");
    }
    return bytes.substr(20, size_t(jsonBytes));
}

// A relative URI naming a file inside the model's folder: no scheme, no
// absolute path, no '..' segment (checked before tinygltf sees the file).
void checkFileUri(const std::string& uri, const std::string& file, const std::string& where) {
    const auto refuse = [&](const std::string& why) {
        throw Error(file, where + ": uri '" + uri.substr(0, 200) + "' " + why);
    };
    if (uri.empty()) refuse("is empty");
    if (uri.front() == '/' || uri.front() == '\\')
        refuse("is an absolute path; only paths relative to the model are read");
    const size_t colon = uri.find(':'), slash = uri.find('/');
    if (colon != std::string::npos && (slash == std::string::npos || colon < slash))
        refuse("has a scheme; only data: URIs and paths relative to the model are read");
    size_t start = 0;
    while (start <= uri.size()) {
        size_t end = uri.find_first_of("/\\", start);
        if (end == std::string::npos) end = uri.size();
        const std::string segment = uri.substr(start, end - start);
        if (segment == ".." || segment == "%2e%2e" || segment == "%2E%2E")
            refuse("leaves the model's folder; only files inside it are read");
        start = end + 1;
    }
}

// The buffer and image URIs of the JSON, checked before any is opened; each
// buffer's declared length must fit the memory budget.
void checkUris(const std::string& jsonText, const std::string& file) {
    nlohmann::json json;
    try {
        json = nlohmann::json::parse(jsonText);
    } catch (const nlohmann::json::exception& e) {
        throw Error(file, std::string("invalid glTF JSON: ") + e.what());
    }
    if (!json.is_object()) throw Error(file, "invalid glTF: the top level is not a JSON object");
    for (const char* kind : {"buffers", "images"}) {
        if (!json.contains(kind)) continue;
        const nlohmann::json& list = json[kind];
        if (!list.is_array()) throw Error(file, std::string("/") + kind + " is not an array");
        for (size_t i = 0; i < list.size(); ++i) {
            const std::string where = std::string("/") + kind + "/" + std::to_string(i);
            if (!list[i].is_object()) throw Error(file, where + " is not an object");
            if (list[i].contains("byteLength")) {
                const nlohmann::json& length = list[i]["byteLength"];
                if (!length.is_number_unsigned() || length.get<uint64_t>() > kMemoryBudgetBytes)
                    throw Error(file, where + "/byteLength is not a length within the memory budget");
            }
            if (!list[i].contains("uri")) continue;
            if (!list[i]["uri"].is_string()) throw Error(file, where + "/uri is not a string");
            const std::string uri = list[i]["uri"].get<std::string>();
            if (uri.rfind("data:", 0) != 0) checkFileUri(uri, file, where);
        }
    }
}

// The files tinygltf opens: regular, within the budget, inside the model's
// folder once links are followed; images are not read (no texture is mapped).
struct Folder {
    fs::path root;  // canonical
};

bool fileExists(const std::string& path, void*) {
    std::error_code ec;
    return fs::is_regular_file(path, ec);
}

std::string expandNothing(const std::string& path, void*) { return path; }

bool isImagePath(const fs::path& p) {
    std::string ext = p.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return ext == ".png" || ext == ".jpg" || ext == ".jpeg" || ext == ".ktx2" || ext == ".webp" || ext == ".bmp";
}

bool readWholeFile(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* user) {
    const Folder& folder = *static_cast<const Folder*>(user);
    try {
        std::error_code ec;
        const fs::path canonical = fs::weakly_canonical(path, ec);
        const auto [rootEnd, unused] =
            std::mismatch(folder.root.begin(), folder.root.end(), canonical.begin(), canonical.end());
        if (ec || rootEnd != folder.root.end())
            throw Error(path, "is outside the model's folder; only files inside it are read");
        if (isImagePath(path)) {
            if (err) *err += "image file not read (Lucent maps no texture): " + path + "\n";
            return false;
        }
        const std::string bytes = readBytes(path, "glTF buffer");
        out->assign(bytes.begin(), bytes.end());
        return true;
    } catch (const Error& e) {
        if (err) *err += std::string(e.what()) + "\n";
        return false;
    }
}

bool writeNothing(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
    if (err) *err += "Lucent never writes through tinygltf\n";
    return false;
}

bool ignoreImage(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int, void*) {
    return true;
}

// tinygltf's messages, one line each.
std::vector<std::string> lines(const std::string& text) {
    std::vector<std::string> out;
    size_t start = 0;
    while (start < text.size()) {
        size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        if (end > start) out.push_back(text.substr(start, end - start));
        start = end + 1;
    }
    return out;
}

}  // namespace

tinygltf::Model readModel(const fs::path& file, std::vector<std::string>& warnings) {
    const std::string name = file.string();
    const std::string bytes = readBytes(file, "glTF file");
    uint64_t binBytes = 0;
    checkUris(isBinary(file) ? glbJson(bytes, name, binBytes) : bytes, name);

    Folder folder;
    std::error_code ec;
    folder.root = fs::weakly_canonical(fs::absolute(file).parent_path(), ec);
    tinygltf::TinyGLTF loader;
    loader.SetFsCallbacks({&fileExists, &expandNothing, &readWholeFile, &writeNothing, &folder});
    loader.SetImageLoader(&ignoreImage, nullptr);
    tinygltf::Model model;
    std::string err, warn;
    const std::string baseDir = file.parent_path().empty() ? "." : file.parent_path().string();
    const bool ok =
        isBinary(file)
            ? loader.LoadBinaryFromMemory(&model, &err, &warn, reinterpret_cast<const unsigned char*>(bytes.data()),
                                          unsigned(bytes.size()), baseDir)
            : loader.LoadASCIIFromString(&model, &err, &warn, bytes.data(), unsigned(bytes.size()), baseDir);
    if (!ok) {
        const std::vector<std::string> errors = lines(err);
        throw Error(name, errors.empty() ? "tinygltf could not read it" : errors.front());
    }
    for (const std::string& w : lines(warn)) warnings.push_back(name + ": " + w);
    return model;
}

namespace {

glm::dmat4 localMatrix(const tinygltf::Node& node, const std::string& file, int index) {
    const auto fail = [&](const std::string& what) {
        throw Error(file, "/nodes/" + std::to_string(index) + ": " + what);
    };
    for (const auto* v : {&node.matrix, &node.translation, &node.rotation, &node.scale})
        for (double x : *v)
            if (!std::isfinite(x) || std::abs(x) > 1e13) fail("a transform value is not finite");
    if (node.matrix.size() == 16) {
        glm::dmat4 m;
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r) m[c][r] = node.matrix[size_t(4 * c + r)];
        return m;
    }
    if (!node.matrix.empty()) fail("matrix must hold 16 numbers");
    glm::dmat4 t(1.0), r(1.0), s(1.0);
    if (node.translation.size() == 3)
        t[3] = glm::dvec4(node.translation[0], node.translation[1], node.translation[2], 1);
    if (node.rotation.size() == 4) {
        glm::dquat q(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);
        const double length = glm::length(q);
        if (!(length > 0.0)) fail("rotation is not a unit quaternion");
        r = glm::dmat4(glm::mat3_cast(q / length));
    }
    if (node.scale.size() == 3) s = glm::scale(glm::dmat4(1.0), Vec3(node.scale[0], node.scale[1], node.scale[2]));
    return t * r * s;
}

void placeNode(const tinygltf::Model& model, int node, const glm::dmat4& parent, const std::string& file,
               std::vector<bool>& reached, std::vector<PlacedNode>& out) {
    if (node < 0 || size_t(node) >= model.nodes.size())
        throw Error(file, "refers to node " + std::to_string(node) + " of " + std::to_string(model.nodes.size()));
    if (reached[size_t(node)])
        throw Error(file, "/nodes/" + std::to_string(node) + " is reached twice; glTF's nodes form a tree");
    reached[size_t(node)] = true;
    const tinygltf::Node& n = model.nodes[size_t(node)];
    const auto check = [&](int index, size_t count, const char* what) {
        if (index >= 0 && size_t(index) >= count)
            throw Error(file, "/nodes/" + std::to_string(node) + " refers to " + what + " " + std::to_string(index) +
                                  " of " + std::to_string(count));
    };
    check(n.mesh, model.meshes.size(), "mesh");
    check(n.camera, model.cameras.size(), "camera");
    check(n.skin, model.skins.size(), "skin");
    const glm::dmat4 world = parent * localMatrix(model.nodes[size_t(node)], file, node);
    out.push_back({node, world});
    for (int child : model.nodes[size_t(node)].children) placeNode(model, child, world, file, reached, out);
}

}  // namespace

std::vector<PlacedNode> placedNodes(const tinygltf::Model& model, const std::string& file) {
    std::vector<int> roots;
    if (!model.scenes.empty()) {
        const int scene = model.defaultScene >= 0 ? model.defaultScene : 0;
        if (size_t(scene) >= model.scenes.size())
            throw Error(file, "the default scene " + std::to_string(scene) + " does not exist");
        roots = model.scenes[size_t(scene)].nodes;
    } else {
        std::vector<bool> isChild(model.nodes.size(), false);
        for (const auto& n : model.nodes)
            for (int c : n.children)
                if (c >= 0 && size_t(c) < model.nodes.size()) isChild[size_t(c)] = true;
        for (size_t i = 0; i < model.nodes.size(); ++i)
            if (!isChild[i]) roots.push_back(int(i));
    }
    std::vector<bool> reached(model.nodes.size(), false);
    std::vector<PlacedNode> out;
    for (int root : roots) placeNode(model, root, glm::dmat4(1.0), file, reached, out);
    return out;
}

namespace {

// The bytes of one accessor, each element checked to lie inside its buffer.
struct AccessorView {
    const unsigned char* data = nullptr;
    size_t count = 0, stride = 0;
    int componentType = 0;
};

AccessorView viewOf(const tinygltf::Model& model, int index, int type, std::initializer_list<int> componentTypes,
                    const std::string& what, const std::string& file) {
    const std::string where = "/accessors/" + std::to_string(index);
    if (index < 0 || size_t(index) >= model.accessors.size())
        throw Error(file,
                    "refers to accessor " + std::to_string(index) + " of " + std::to_string(model.accessors.size()));
    const tinygltf::Accessor& a = model.accessors[size_t(index)];
    if (a.sparse.isSparse) throw Error(file, where + ": sparse accessors are not read");
    if (a.type != type ||
        std::find(componentTypes.begin(), componentTypes.end(), a.componentType) == componentTypes.end())
        throw Error(file, where + ": " + what);
    if (a.bufferView < 0 || size_t(a.bufferView) >= model.bufferViews.size())
        throw Error(file, where + ": has no buffer view");
    const tinygltf::BufferView& v = model.bufferViews[size_t(a.bufferView)];
    if (v.buffer < 0 || size_t(v.buffer) >= model.buffers.size())
        throw Error(file, where + ": its buffer view has no buffer");
    const tinygltf::Buffer& b = model.buffers[size_t(v.buffer)];
    const int componentBytes = tinygltf::GetComponentSizeInBytes(uint32_t(a.componentType));
    const int components = tinygltf::GetNumComponentsInType(uint32_t(a.type));
    if (componentBytes <= 0 || components <= 0) throw Error(file, where + ": unknown component type");
    const uint64_t element = uint64_t(componentBytes) * uint64_t(components);
    const uint64_t stride = v.byteStride ? uint64_t(v.byteStride) : element;
    if (stride < element) throw Error(file, where + ": byteStride is smaller than one element");
    const uint64_t viewEnd = uint64_t(v.byteOffset) + uint64_t(v.byteLength);
    if (viewEnd > b.data.size() || viewEnd < v.byteOffset)
        throw Error(file, where + ": its buffer view runs past the end of its buffer");
    AccessorView out;
    out.count = a.count;
    if (out.count > 0) {
        const uint64_t last = uint64_t(a.byteOffset) + (uint64_t(a.count) - 1) * stride + element;
        if (a.count > b.data.size() || last > v.byteLength)
            throw Error(file, where + ": " + std::to_string(a.count) + " elements run past the end of its buffer view");
    }
    out.data = b.data.data() + v.byteOffset + a.byteOffset;
    out.stride = size_t(stride);
    out.componentType = a.componentType;
    return out;
}

std::vector<Vec3> readPositions(const tinygltf::Model& model, int index, const std::string& file) {
    const AccessorView v =
        viewOf(model, index, TINYGLTF_TYPE_VEC3, {TINYGLTF_COMPONENT_TYPE_FLOAT}, "positions must be float VEC3", file);
    std::vector<Vec3> out(v.count);
    for (size_t i = 0; i < v.count; ++i) {
        float p[3];
        std::memcpy(p, v.data + i * v.stride, sizeof p);
        for (float x : p)
            if (!std::isfinite(x))
                throw Error(
                    file, "/accessors/" + std::to_string(index) + ": position " + std::to_string(i) + " is not finite");
        out[i] = Vec3(p[0], p[1], p[2]);
    }
    return out;
}

std::vector<uint32_t> readIndices(const tinygltf::Model& model, int index, size_t vertices, const std::string& file) {
    const AccessorView v = viewOf(model, index, TINYGLTF_TYPE_SCALAR,
                                  {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                                   TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT},
                                  "indices must be unsigned integer SCALARs", file);
    std::vector<uint32_t> out(v.count);
    for (size_t i = 0; i < v.count; ++i) {
        const unsigned char* p = v.data + i * v.stride;
        uint32_t x = 0;
        switch (v.componentType) {
            case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
                x = *p;
                break;
            case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
                uint16_t s;
                std::memcpy(&s, p, 2);
                x = s;
                break;
            }
            case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
                std::memcpy(&x, p, 4);
                break;
            default:
                throw Error(file, "/accessors/" + std::to_string(index) + ": indices must be unsigned integers");
        }
        if (x >= vertices)
            throw Error(file, "/accessors/" + std::to_string(index) + ": index " + std::to_string(x) + " of " +
                                  std::to_string(vertices) + " vertices");
        out[i] = x;
    }
    return out;
}

// Triangle lists, strips and fans as glTF 2.0 (section 3.7.2.1) orders them.
void appendTriangles(int mode, const std::vector<uint32_t>& idx, uint32_t base,
                     std::vector<std::array<uint32_t, 3>>& out) {
    const auto add = [&](uint32_t a, uint32_t b, uint32_t c) { out.push_back({base + a, base + b, base + c}); };
    if (mode == TINYGLTF_MODE_TRIANGLES) {
        for (size_t i = 0; i + 2 < idx.size(); i += 3) add(idx[i], idx[i + 1], idx[i + 2]);
    } else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
        for (size_t i = 0; i + 2 < idx.size(); ++i)
            i % 2 == 0 ? add(idx[i], idx[i + 1], idx[i + 2]) : add(idx[i + 1], idx[i], idx[i + 2]);
    } else {
        for (size_t i = 1; i + 1 < idx.size(); ++i) add(idx[i], idx[i + 1], idx[0]);
    }
}

}  // namespace

RawTriangles meshTriangles(const tinygltf::Model& model, int mesh, const std::string& file,
                           std::vector<std::string>& warnings) {
    if (mesh < 0 || size_t(mesh) >= model.meshes.size())
        throw Error(file, "refers to mesh " + std::to_string(mesh) + " of " + std::to_string(model.meshes.size()));
    RawTriangles out;
    const auto& primitives = model.meshes[size_t(mesh)].primitives;
    for (size_t p = 0; p < primitives.size(); ++p) {
        const tinygltf::Primitive& prim = primitives[p];
        const std::string where = "/meshes/" + std::to_string(mesh) + "/primitives/" + std::to_string(p);
        const int mode = prim.mode < 0 ? TINYGLTF_MODE_TRIANGLES : prim.mode;
        if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
            mode != TINYGLTF_MODE_TRIANGLE_FAN) {
            warnings.push_back(file + ": " + where + ": points and lines bound no volume; left out");
            continue;
        }
        const auto position = prim.attributes.find("POSITION");
        if (position == prim.attributes.end()) throw Error(file, where + ": has no POSITION attribute");
        const std::vector<Vec3> positions = readPositions(model, position->second, file);
        std::vector<uint32_t> indices;
        if (prim.indices >= 0) {
            indices = readIndices(model, prim.indices, positions.size(), file);
        } else {
            indices.resize(positions.size());
            for (size_t i = 0; i < indices.size(); ++i) indices[i] = uint32_t(i);
        }
        if (out.positions.size() + positions.size() > uint64_t(UINT32_MAX))
            throw Error(file, "/meshes/" + std::to_string(mesh) + ": too many vertices");
        appendTriangles(mode, indices, uint32_t(out.positions.size()), out.triangles);
        out.positions.insert(out.positions.end(), positions.begin(), positions.end());
    }
    return out;
}

RawTriangles weldVertices(const RawTriangles& mesh, double tolerance) {
    // Cells of the tolerance's size: a vertex's twin lies in its cell or a neighbour.
    using Cell = std::tuple<int64_t, int64_t, int64_t>;
    const double cellSize = tolerance > 0.0 ? tolerance : 1.0;
    const auto cellOf = [&](const Vec3& p) {
        return Cell{int64_t(std::floor(p.x / cellSize)), int64_t(std::floor(p.y / cellSize)),
                    int64_t(std::floor(p.z / cellSize))};
    };
    std::map<Cell, std::vector<uint32_t>> cells;
    std::vector<uint32_t> remap(mesh.positions.size());
    RawTriangles out;
    for (size_t i = 0; i < mesh.positions.size(); ++i) {
        const Vec3& p = mesh.positions[i];
        const auto [cx, cy, cz] = cellOf(p);
        uint32_t found = UINT32_MAX;
        for (int64_t dx = -1; dx <= 1 && found == UINT32_MAX; ++dx)
            for (int64_t dy = -1; dy <= 1 && found == UINT32_MAX; ++dy)
                for (int64_t dz = -1; dz <= 1 && found == UINT32_MAX; ++dz) {
                    const auto it = cells.find(Cell{cx + dx, cy + dy, cz + dz});
                    if (it == cells.end()) continue;
                    for (uint32_t j : it->second)
                        if (glm::length(out.positions[j] - p) <= tolerance) {
                            found = j;
                            break;
                        }
                }
        if (found == UINT32_MAX) {
            found = uint32_t(out.positions.size());
            out.positions.push_back(p);
            cells[Cell{cx, cy, cz}].push_back(found);
        }
        remap[i] = found;
    }
    for (const auto& t : mesh.triangles) {
        const std::array<uint32_t, 3> w{remap[t[0]], remap[t[1]], remap[t[2]]};
        if (w[0] != w[1] && w[1] != w[2] && w[0] != w[2]) out.triangles.push_back(w);
    }
    return out;
}

}  // namespace lucent::gltf
