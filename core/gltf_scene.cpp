#include "core/gltf_scene.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <set>

#include "core/error.h"
#include "core/fingerprint.h"
#include "core/internal/gltf_model.h"
#include "core/limits.h"

namespace lucent {
namespace {

namespace fs = std::filesystem;
using tinygltf::Model;
using tinygltf::Value;

// KHR_lights_punctual gives candela (point, spot) and lux (directional); Lucent
// takes W/sr and W/m^2. 683 lm/W is the luminous efficacy of 555 nm light, the
// factor Blender's glTF exporter multiplies its watts by.
constexpr double kLumensPerWatt = 683.0;
// Vertices closer than this share of the mesh's bounding diagonal are one vertex.
constexpr double kWeldTolerance = 1e-6;
// Image size when the camera gives only an aspect ratio.
constexpr int kImageHeight = 512;

std::string lowercase(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return s;
}

// A number of a glTF extension object, its default when absent; finite or an Error.
double number(const Value& object, const std::string& key, double fallback, const std::string& file,
              const std::string& where) {
    if (!object.Has(key)) return fallback;
    const Value& v = object.Get(key);
    if (!v.IsNumber() || !std::isfinite(v.GetNumberAsDouble()))
        throw Error(file, where + "/" + key + " is not a finite number");
    return v.GetNumberAsDouble();
}

Rgb colour(const Value& object, const std::string& key, Rgb fallback, const std::string& file,
           const std::string& where) {
    if (!object.Has(key)) return fallback;
    const Value& v = object.Get(key);
    if (!v.IsArray() || v.ArrayLen() != 3) throw Error(file, where + "/" + key + " is not an array of 3 numbers");
    Rgb c;
    for (int i = 0; i < 3; ++i) {
        const Value& x = v.Get(i);
        if (!x.IsNumber() || !std::isfinite(x.GetNumberAsDouble()) || x.GetNumberAsDouble() < 0.0 ||
            x.GetNumberAsDouble() > 1.0)
            throw Error(file, where + "/" + key + " must hold numbers in [0, 1]");
        c[i] = x.GetNumberAsDouble();
    }
    return c;
}

const Value* extension(const tinygltf::ExtensionMap& extensions, const std::string& name) {
    const auto it = extensions.find(name);
    return it == extensions.end() ? nullptr : &it->second;
}

// The world matrix as a Similarity when it is one (uniform positive scale,
// proper rotation, translation), within the scales Lucent places objects at.
std::optional<Similarity> similarityOf(const glm::dmat4& m) {
    const glm::dmat3 a(m);
    const double det = glm::determinant(a);
    if (!(det > 0.0)) return std::nullopt;
    const double scale = std::cbrt(det);
    if (scale < kMinScale || scale > kMaxScale) return std::nullopt;
    const glm::dmat3 r = a / scale;
    const glm::dmat3 rtr = glm::transpose(r) * r;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            if (std::abs(rtr[i][j] - (i == j ? 1.0 : 0.0)) > 1e-6) return std::nullopt;
    Similarity s;
    s.scale = scale;
    s.rotation = r;
    s.translation = Vec3(m[3]);
    return s;
}

// The node's mesh in the space its object is placed from: the node's own when
// its world matrix is a similarity (the object's transform), the scene's when
// not (baked); welded and ready for the closedness check.
struct NodeMesh {
    gltf::RawTriangles triangles;
    std::optional<Similarity> placement;  // nullopt: baked
};

NodeMesh nodeMesh(const Model& model, const gltf::PlacedNode& placed, const std::string& file,
                  std::vector<std::string>& warnings) {
    NodeMesh out;
    gltf::RawTriangles raw = gltf::meshTriangles(model, model.nodes[size_t(placed.node)].mesh, file, warnings);
    out.placement = similarityOf(placed.world);
    if (!out.placement)
        for (Vec3& p : raw.positions) p = Vec3(placed.world * glm::dvec4(p, 1.0));
    Bounds3 bounds;
    for (const Vec3& p : raw.positions) bounds.extend(p);
    out.triangles = gltf::weldVertices(raw, kWeldTolerance * (raw.positions.empty() ? 0.0 : bounds.diagonal()));
    return out;
}

std::string nodeName(const Model& model, int node) {
    const tinygltf::Node& n = model.nodes[size_t(node)];
    if (!n.name.empty()) return n.name;
    if (n.mesh >= 0 && !model.meshes[size_t(n.mesh)].name.empty()) return model.meshes[size_t(n.mesh)].name;
    return "node" + std::to_string(node);
}

// A name safe in a file name: letters, digits, '-', '_' and '.', nothing else.
std::string fileSafe(const std::string& name) {
    std::string out;
    for (char c : name) out += std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' ? c : '_';
    return out.empty() ? "object" : out.substr(0, 100);
}

// The features of the file Lucent does not map, one warning line each.
struct Dropped {
    std::set<std::string> features;
    void note(const std::string& feature) { features.insert(feature); }
};

bool hasTexture(const tinygltf::Material& m) {
    return m.pbrMetallicRoughness.baseColorTexture.index >= 0 ||
           m.pbrMetallicRoughness.metallicRoughnessTexture.index >= 0 || m.normalTexture.index >= 0 ||
           m.occlusionTexture.index >= 0 || m.emissiveTexture.index >= 0;
}

// What a material makes of the object: a medium, or nothing (opaque, skipped).
std::optional<MediumDesc> mediumOf(const Model& model, int index, const std::string& file, Dropped& dropped,
                                   bool& absorbsOnly) {
    if (index < 0) return std::nullopt;  // glTF's default material is opaque
    if (size_t(index) >= model.materials.size())
        throw Error(file,
                    "refers to material " + std::to_string(index) + " of " + std::to_string(model.materials.size()));
    const tinygltf::Material& m = model.materials[size_t(index)];
    const std::string where = "/materials/" + std::to_string(index);
    const std::string name = m.name.empty() ? where : "'" + m.name + "'";
    if (hasTexture(m)) dropped.note("textures");
    if (extension(m.extensions, "KHR_materials_emissive_strength") ||
        std::any_of(m.emissiveFactor.begin(), m.emissiveFactor.end(), [](double e) { return e > 0.0; }))
        dropped.note("emission");
    const Value* volume = extension(m.extensions, "KHR_materials_volume");
    if (!volume) {
        for (const char* thin : {"KHR_materials_transmission", "KHR_materials_diffuse_transmission"})
            if (extension(m.extensions, thin))
                throw Error(file, "material " + name + ": " + thin +
                                      " without KHR_materials_volume is a thin surface with no interior; Lucent "
                                      "renders volumes (add KHR_materials_volume)");
        return std::nullopt;
    }
    const std::string v = where + "/extensions/KHR_materials_volume";
    MediumDesc medium;
    // Extinction per channel from the colour a path of attenuationDistance keeps
    // (KHR_materials_volume: c = exp(-sigma_t d)); a colour of 0 is capped at 1e-30.
    const Rgb c = colour(*volume, "attenuationColor", Rgb(1.0), file, v);
    const double d = number(*volume, "attenuationDistance", INFINITY, file, v);
    if (!(d > 0.0)) throw Error(file, v + "/attenuationDistance must be positive");
    for (int i = 0; i < 3; ++i) medium.sigmaT[i] = std::isinf(d) ? 0.0 : -std::log(std::max(c[i], 1e-30)) / d;
    if (volume->Has("thicknessTexture")) dropped.note("textures");
    medium.ior = 1.5;  // KHR_materials_ior's default, which glTF assumes without the extension
    if (const Value* ior = extension(m.extensions, "KHR_materials_ior")) {
        medium.ior = number(*ior, "ior", 1.5, file, where + "/extensions/KHR_materials_ior");
        if (!(medium.ior >= 1.0 && medium.ior <= 4.0))
            throw Error(file, "material " + name + ": ior " + std::to_string(medium.ior) +
                                  " is outside the [1, 4] Lucent renders");
    }
    if (const Value* scatter = extension(m.extensions, "KHR_materials_volume_scatter")) {
        const std::string s = where + "/extensions/KHR_materials_volume_scatter";
        medium.g = std::clamp(number(*scatter, "scatterAnisotropy", 0.0, file, s), -0.999, 0.999);
        const Rgb multiscatter = colour(*scatter, "multiscatterColor", Rgb(0.0), file, s);
        for (int i = 0; i < 3; ++i) medium.albedo[i] = singleScatteringAlbedo(multiscatter[i], medium.g);
        absorbsOnly = false;
    } else {
        medium.albedo = Rgb(0.0);
        absorbsOnly = true;
    }
    return medium;
}

Light lightOf(const Model& model, const gltf::PlacedNode& placed, int index, const std::string& file,
              std::vector<std::string>& warnings) {
    if (index < 0 || size_t(index) >= model.lights.size())
        throw Error(file, "refers to light " + std::to_string(index) + " of " + std::to_string(model.lights.size()));
    const tinygltf::Light& g = model.lights[size_t(index)];
    const std::string where = "/extensions/KHR_lights_punctual/lights/" + std::to_string(index);
    Rgb c(1.0);
    if (!g.color.empty()) {
        if (g.color.size() != 3) throw Error(file, where + "/color is not an array of 3 numbers");
        for (int i = 0; i < 3; ++i) c[i] = g.color[size_t(i)];
    }
    if (!std::isfinite(g.intensity) || g.intensity < 0.0 || g.intensity > kMaxMagnitude ||
        !(c.r >= 0.0 && c.g >= 0.0 && c.b >= 0.0 && c.r <= 1.0 && c.g <= 1.0 && c.b <= 1.0))
        throw Error(file, where + ": color and intensity must be finite, color in [0, 1], intensity >= 0");
    if (g.range > 0.0)
        warnings.push_back(file + ": " + where + ": range is ignored (Lucent's lights reach everywhere)");
    Light l;
    l.power = c * (g.intensity / kLumensPerWatt);
    const Vec3 forward = Vec3(placed.world * glm::dvec4(0.0, 0.0, -1.0, 0.0));
    if (!(glm::length(forward) > 0.0) || !isFinite(forward))
        throw Error(file, where + ": its node's transform is degenerate");
    if (g.type == "directional") {
        l.type = Light::Type::Directional;
        l.direction = glm::normalize(forward);
        return l;
    }
    l.type = Light::Type::Point;
    l.position = Vec3(placed.world[3]);
    if (g.type == "spot") {
        SpotCone cone;
        cone.axis = glm::normalize(forward);
        cone.innerDegrees = glm::degrees(g.spot.innerConeAngle);
        cone.outerDegrees = glm::degrees(g.spot.outerConeAngle);
        if (!(cone.innerDegrees >= 0.0 && cone.innerDegrees < cone.outerDegrees && cone.outerDegrees <= 90.0 &&
              cone.outerDegrees >= 1e-3))
            throw Error(file, where + "/spot: needs 0 <= innerConeAngle < outerConeAngle <= pi/2");
        l.spot = cone;
    } else if (g.type != "point") {
        throw Error(file, where + ": unknown light type '" + g.type + "' (point, spot or directional)");
    }
    return l;
}

Camera cameraOf(const Model& model, const gltf::PlacedNode& placed, const std::string& file) {
    const tinygltf::Camera& g = model.cameras[size_t(model.nodes[size_t(placed.node)].camera)];
    const std::string where = "/cameras/" + std::to_string(model.nodes[size_t(placed.node)].camera);
    if (g.type != "perspective") throw Error(file, where + ": only perspective cameras are supported");
    Camera c;
    c.fovYDegrees = glm::degrees(g.perspective.yfov);
    if (!(c.fovYDegrees >= 1e-3 && c.fovYDegrees <= 179.0)) throw Error(file, where + ": yfov is outside (0, pi)");
    c.height = kImageHeight;
    if (g.perspective.aspectRatio > 0.0)
        c.width = int(std::clamp(std::lround(kImageHeight * g.perspective.aspectRatio), 1L, 16384L));
    else
        c.width = kImageHeight;
    c.position = Vec3(placed.world[3]);
    const Vec3 forward = Vec3(placed.world * glm::dvec4(0.0, 0.0, -1.0, 0.0));
    const Vec3 up = Vec3(placed.world * glm::dvec4(0.0, 1.0, 0.0, 0.0));
    if (!(glm::length(forward) > 0.0) || !(glm::length(glm::cross(forward, up)) > 0.0) || !isFinite(c.position))
        throw Error(file, where + ": its node's transform is degenerate");
    c.target = c.position + glm::normalize(forward);
    c.up = glm::normalize(up);
    return c;
}

// Without a camera in the file: one on +z looking at the objects' bounding
// sphere, which fills 80% of a 40 degree view.
Camera framingCamera(const Bounds3& bounds) {
    Camera c;
    const Vec3 centre = 0.5 * (bounds.min + bounds.max);
    const double radius = 0.5 * bounds.diagonal();
    c.fovYDegrees = 40.0;
    c.target = centre;
    c.position = centre + Vec3(0.0, 0.0, radius / std::sin(glm::radians(0.8 * c.fovYDegrees / 2.0)));
    c.width = c.height = kImageHeight;
    return c;
}

struct Import {
    SceneDesc scene;
    Dropped dropped;
    Bounds3 bounds;
    std::set<std::string> names;
    bool absorbsOnly = false;
};

void addObject(const Model& model, const gltf::PlacedNode& placed, const fs::path& file, Import& in) {
    const std::string name = file.string();
    const tinygltf::Mesh& mesh = model.meshes.at(size_t(model.nodes[size_t(placed.node)].mesh));
    int material = mesh.primitives.empty() ? -1 : mesh.primitives.front().material;
    for (const auto& p : mesh.primitives) {
        if (!p.targets.empty()) in.dropped.note("morph targets");
        if (p.material != material)
            in.scene.warnings.push_back(name + ": mesh '" + mesh.name + "' has primitives of different materials; " +
                                        "the object takes the first primitive's");
    }
    bool absorbsOnly = false;
    const std::optional<MediumDesc> medium = mediumOf(model, material, name, in.dropped, absorbsOnly);
    std::string objectName = nodeName(model, placed.node);
    if (!medium) {
        in.scene.warnings.push_back(name + ": node '" + objectName +
                                    "' has no KHR_materials_volume: it is opaque and left out");
        return;
    }
    in.absorbsOnly = in.absorbsOnly || absorbsOnly;
    for (int n = 2; in.names.count(objectName); ++n)
        objectName = nodeName(model, placed.node) + "-" + std::to_string(n);
    in.names.insert(objectName);

    std::vector<std::string> meshWarnings;
    const NodeMesh m = nodeMesh(model, placed, name, meshWarnings);
    for (const Vec3& p : m.triangles.positions) in.bounds.extend(m.placement ? m.placement->point(p) : p);
    if (!m.placement)
        in.scene.warnings.push_back(
            name + ": node '" + objectName +
            "': its transform is not a rotation, uniform scale and translation; baked into the mesh");
    ObjectDesc o;
    o.name = objectName;
    o.mesh = file;
    o.gltfNode = placed.node;
    o.medium = *medium;
    o.transform = m.placement.value_or(Similarity{});
    o.samples = file.parent_path() / (file.stem().string() + "." + fileSafe(objectName) + ".lsf");
    // The welded triangles and the extinction: what the samples depend on (as
    // for scene files, not the ior, albedo or g, which every method takes at draw time).
    Fingerprint fp;
    fp.addText("glTF node mesh");
    fp.addBytes(m.triangles.positions.data(), m.triangles.positions.size() * sizeof(Vec3));
    fp.addBytes(m.triangles.triangles.data(), m.triangles.triangles.size() * sizeof(m.triangles.triangles[0]));
    fp.addBytes(&o.medium.sigmaT, sizeof o.medium.sigmaT);
    o.fingerprint = fp.value();
    in.scene.objects.push_back(std::move(o));
}

void noteUnmapped(const Model& model, Import& in) {
    if (!model.skins.empty()) in.dropped.note("skins");
    if (!model.animations.empty()) in.dropped.note("animations");
    if (!model.textures.empty()) in.dropped.note("textures");
    for (const std::string& f : in.dropped.features)
        in.scene.warnings.push_back(in.scene.file.string() + ": " + f + " are not mapped (docs/gltf.md); left out");
}

}  // namespace

bool isGltfFile(const fs::path& file) {
    const std::string ext = lowercase(file.extension().string());
    return ext == ".gltf" || ext == ".glb";
}

double singleScatteringAlbedo(double multiscatter, double g) {
    // rho_ms(s) = (1 - s)(1 - 0.139 s) / (1 + 1.17 s) falls from 1 at s = 0 to 0
    // at s = 1; its inverse is the smaller root of
    // 0.139 s^2 - (1.139 + 1.17 rho) s + (1 - rho) = 0.
    const double rho = std::clamp(multiscatter, 0.0, 1.0);
    const double b = 1.139 + 1.17 * rho;
    const double s = std::clamp((b - std::sqrt(b * b - 4.0 * 0.139 * (1.0 - rho))) / (2.0 * 0.139), 0.0, 1.0);
    // s^2 = (1 - a) / (1 - g a)  =>  a = (1 - s^2) / (1 - g s^2).
    const double s2 = s * s;
    return std::clamp((1.0 - s2) / (1.0 - g * s2), 0.0, 1.0);
}

SceneDesc importGltfScene(const fs::path& file, const std::string& cameraName) {
    const std::string name = file.string();
    Import in;
    in.scene.file = file;
    in.scene.units = "m";  // glTF's unit of length
    const Model model = gltf::readModel(file, in.scene.warnings);
    const std::vector<gltf::PlacedNode> nodes = gltf::placedNodes(model, name);
    std::optional<Camera> camera;
    std::vector<std::string> cameraNames;
    for (const gltf::PlacedNode& placed : nodes) {
        const tinygltf::Node& node = model.nodes[size_t(placed.node)];
        if (node.skin >= 0) in.dropped.note("skins");
        if (node.mesh >= 0) addObject(model, placed, file, in);
        if (const Value* lights = extension(node.extensions, "KHR_lights_punctual")) {
            if (!lights->Has("light") || !lights->Get("light").IsInt())
                throw Error(name,
                            "/nodes/" + std::to_string(placed.node) + "/extensions/KHR_lights_punctual has no light");
            in.scene.lights.push_back(
                lightOf(model, placed, lights->Get("light").GetNumberAsInt(), name, in.scene.warnings));
            if (in.scene.lights.size() > kMaxLights)
                throw Error(name, "more than " + std::to_string(kMaxLights) + " lights (docs/robustness.md)");
        }
        if (node.camera >= 0) {
            if (size_t(node.camera) >= model.cameras.size())
                throw Error(name, "/nodes/" + std::to_string(placed.node) + " refers to a camera that does not exist");
            const std::string label = node.name.empty() ? model.cameras[size_t(node.camera)].name : node.name;
            cameraNames.push_back(label);
            const bool wanted =
                cameraName.empty() ? !camera
                                   : (cameraName == node.name || cameraName == model.cameras[size_t(node.camera)].name);
            if (wanted && !camera) camera = cameraOf(model, placed, name);
        }
    }
    if (in.scene.objects.empty())
        throw Error(name, "no node has a mesh with KHR_materials_volume: nothing translucent to render (docs/gltf.md)");
    if (!cameraName.empty() && !camera) {
        std::string known;
        for (const std::string& c : cameraNames) known += (known.empty() ? "" : ", ") + ("'" + c + "'");
        throw Error(name,
                    "has no camera named '" + cameraName + "' (cameras: " + (known.empty() ? "none" : known) + ")");
    }
    in.scene.camera = camera ? *camera : framingCamera(in.bounds);
    if (in.absorbsOnly)
        in.scene.warnings.push_back(name +
                                    ": a volume without KHR_materials_volume_scatter absorbs and does not scatter "
                                    "(coloured glass): lit by punctual lights it sends no light to the camera, and "
                                    "every method draws it black (docs/gltf.md)");
    noteUnmapped(model, in);
    return in.scene;
}

TriangleMesh loadGltfMesh(const fs::path& file, int node, std::vector<std::string>& warnings) {
    const std::string name = file.string();
    std::vector<std::string> ignored;  // the import told them
    const Model model = gltf::readModel(file, ignored);
    for (const gltf::PlacedNode& placed : gltf::placedNodes(model, name)) {
        if (placed.node != node) continue;
        if (model.nodes[size_t(node)].mesh < 0) break;
        const NodeMesh m = nodeMesh(model, placed, name, ignored);
        const std::string label = name + " (node '" + nodeName(model, node) + "')";
        return closedMesh(m.triangles.positions, m.triangles.triangles, label, warnings);
    }
    throw Error(name, "has no node " + std::to_string(node) + " with a mesh in its scene (was the file replaced?)");
}

}  // namespace lucent
