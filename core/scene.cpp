#include "core/scene.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <optional>
#include <set>
#include <sstream>

#include "core/error.h"
#include "core/fingerprint.h"
#include "core/gltf_scene.h"
#include "core/input_file.h"
#include "core/internal/json_node.h"
#include "core/limits.h"
#include "core/medium_presets.h"

namespace lucent {
namespace {

Camera parseCamera(Node n) {
    n.requireObject();
    Camera c;
    c.position = n.child("position").point();
    c.target = n.child("target").point();
    if (n.has("up")) c.up = n.child("up").direction();
    c.fovYDegrees = n.child("fov_y").number(1e-3, 179.0);
    c.width = n.child("width").integer(1, 16384);
    c.height = n.child("height").integer(1, 16384);
    n.rejectUnknownKeys();
    if (glm::length(c.target - c.position) == 0.0) n.fail("position and target coincide");
    if (glm::length(glm::cross(c.target - c.position, c.up)) == 0.0) n.fail("up is parallel to the view direction");
    return c;
}

Light parseLight(Node n) {
    n.requireObject();
    Light l;
    const std::string type = n.child("type").string();
    if (type == "point") {
        l.type = Light::Type::Point;
        l.position = n.child("position").point();
        l.power = n.child("intensity").rgb(0.0, kMaxMagnitude);
        if (n.has("radius")) l.radius = n.child("radius").number(0.0, kMaxCoordinate);
    } else if (type == "spot") {
        l.type = Light::Type::Point;
        l.position = n.child("position").point();
        l.power = n.child("intensity").rgb(0.0, kMaxMagnitude);
        SpotCone cone;
        cone.axis = n.child("direction").direction();
        if (n.has("outer_angle")) cone.outerDegrees = n.child("outer_angle").number(1e-3, 90.0);
        if (n.has("inner_angle")) {
            Node inner = n.child("inner_angle");
            cone.innerDegrees = inner.number(0.0, 90.0);
            if (!(cone.innerDegrees < cone.outerDegrees)) inner.fail("must be less than outer_angle");
        }
        l.spot = cone;
    } else if (type == "directional") {
        l.type = Light::Type::Directional;
        l.direction = n.child("direction").direction();
        l.power = n.child("irradiance").rgb(0.0, kMaxMagnitude);
    } else {
        n.child("type").fail("unknown light type '" + type + "' (expected point, spot, directional or environment)");
    }
    n.rejectUnknownKeys();
    return l;
}

std::filesystem::path resolve(const std::filesystem::path& sceneFile, const std::string& relative) {
    const std::filesystem::path p(relative);
    return p.is_absolute() ? p : sceneFile.parent_path() / p;
}

EnvironmentDesc parseEnvironment(Node n, const std::filesystem::path& sceneFile) {
    EnvironmentDesc e;
    e.file = resolve(sceneFile, n.child("file").string());
    if (n.has("scale")) e.scale = n.child("scale").number(0.0, kMaxMagnitude);
    if (n.has("rotate")) {
        Node r = n.child("rotate");
        r.requireObject();
        const Vec3 axis = r.child("axis").direction();
        const double degrees = r.child("degrees").number(-1e6, 1e6);
        r.rejectUnknownKeys();
        e.rotation = makeSimilarity(1.0, axis, degrees, Vec3(0.0)).rotation;
    }
    n.rejectUnknownKeys();
    return e;
}

DensityDesc parseDensity(Node n, const std::filesystem::path& sceneFile) {
    n.requireObject();
    DensityDesc d;
    const std::string type = n.child("type").string();
    if (type == "constant") {
        d.type = DensityDesc::Type::Constant;
    } else if (type == "layers") {
        d.type = DensityDesc::Type::Layers;
        Node axis = n.child("axis");
        const std::string a = axis.string();
        if (a != "x" && a != "y" && a != "z") axis.fail("must be \"x\", \"y\" or \"z\"");
        d.axis = a[0] - 'x';
        Node values = n.child("values");
        if (values.arraySize() == 0) values.fail("must hold at least one value");
        for (size_t i = 0; i < values.arraySize(); ++i)
            d.values.push_back(values.element(i).number(0.0, kMaxMagnitude));
    } else if (type == "grid") {
        d.type = DensityDesc::Type::Grid;
        Node file = n.child("file");
        d.file = resolve(sceneFile, file.string());
        if (d.file.extension() == ".vdb") {
            d.gridName = n.has("grid") ? n.child("grid").string() : "density";
        } else {
            Node dims = n.child("dims");
            if (dims.arraySize() != 3) dims.fail("must be an array of 3 integers");
            for (int i = 0; i < 3; ++i) d.dims[i] = dims.element(i).integer(1, 4096);
            Node bounds = n.child("bounds");
            if (bounds.arraySize() != 2) bounds.fail("must be [[min x, y, z], [max x, y, z]]");
            d.bounds.min = bounds.element(0).point();
            d.bounds.max = bounds.element(1).point();
            for (int i = 0; i < 3; ++i)
                if (!(d.bounds.max[i] > d.bounds.min[i])) bounds.fail("max must exceed min on every axis");
        }
    } else {
        n.child("type").fail("unknown density type '" + type + "' (expected constant, layers or grid)");
    }
    n.rejectUnknownKeys();
    return d;
}

// The scene's length unit: what "units" says, or none (coefficients per scene unit).
struct Units {
    std::string name;
    std::optional<double> millimetres;  // per scene unit
};

// A preset gives sigma_t, albedo and g from published coefficients (per mm,
// converted to the scene's unit); explicit keys beside it override them.
MediumDesc parseMedium(Node n, const std::filesystem::path& sceneFile, const Units& units) {
    n.requireObject();
    MediumDesc m;
    const bool preset = n.has("preset");
    if (preset) {
        Node name = n.child("preset");
        const MediumPreset* p = findMediumPreset(name.string());
        if (!p) name.fail("unknown preset '" + name.string() + "' (valid: " + mediumPresetNames() + ")");
        if (!units.millimetres)
            name.fail(
                "a preset needs the scene's top-level \"units\" (\"mm\", \"cm\" or \"m\"): its coefficients "
                "are published per mm");
        m.sigmaT = p->sigmaT() * *units.millimetres;
        m.albedo = p->albedo();
        m.g = std::clamp(p->meanG(), -0.999, 0.999);
    }
    if (!preset || n.has("sigma_t")) m.sigmaT = n.child("sigma_t").rgb(0.0, kMaxMagnitude);
    if (!preset || n.has("albedo")) m.albedo = n.child("albedo").rgb(0.0, 1.0);
    if (std::max({m.sigmaT.r, m.sigmaT.g, m.sigmaT.b}) > kMaxMagnitude)
        n.fail("the preset's sigma_t in these units exceeds 1e30");
    if (n.has("g")) m.g = n.child("g").number(-0.999, 0.999);
    if (n.has("ior")) m.ior = n.child("ior").number(1.0, 4.0);
    if (n.has("density")) m.density = parseDensity(n.child("density"), sceneFile);
    if (n.has("blockers")) {
        Node blockers = n.child("blockers");
        for (size_t i = 0; i < blockers.arraySize(); ++i)
            m.blockers.push_back(resolve(sceneFile, blockers.element(i).string()));
    }
    n.rejectUnknownKeys();
    return m;
}

SurfaceDesc parseSurface(Node n) {
    n.requireObject();
    SurfaceDesc s;
    if (n.has("diffuse")) s.diffuse = n.child("diffuse").rgb(0.0, 1.0);
    if (n.has("specular")) s.specular = n.child("specular").rgb(0.0, 1.0);
    if (n.has("shininess")) s.shininess = n.child("shininess").number(0.0, 1e6);
    n.rejectUnknownKeys();
    return s;
}

// scale, then rotate, then translate, each optional. A scale is one number, or
// three equal ones: the sample file's attenuation holds for uniform scales only.
Similarity parseTransform(Node n) {
    n.requireObject();
    double scale = 1.0, degrees = 0.0;
    Vec3 axis(0.0, 0.0, 1.0), translate(0.0);
    if (n.has("scale")) {
        Node s = n.child("scale");
        if (s.json().is_array()) {
            if (s.arraySize() != 3) s.fail("must be a number or an array of 3 equal numbers");
            scale = s.element(0).number(kMinScale, kMaxScale);
            for (size_t i = 1; i < 3; ++i)
                if (s.element(i).number(kMinScale, kMaxScale) != scale)
                    s.fail(
                        "a non-uniform scale is not supported: the sample file's attenuation holds for uniform "
                        "scales only (scale the mesh itself and preprocess it again)");
        } else {
            scale = s.number(kMinScale, kMaxScale);
        }
    }
    if (n.has("rotate")) {
        Node r = n.child("rotate");
        r.requireObject();
        axis = r.child("axis").direction();
        degrees = r.child("degrees").number(-1e6, 1e6);
        r.rejectUnknownKeys();
    }
    if (n.has("translate")) translate = n.child("translate").point();
    n.rejectUnknownKeys();
    return makeSimilarity(scale, axis, degrees, translate);
}

ObjectDesc parseObject(Node n, const std::filesystem::path& sceneFile, const Units& units) {
    n.requireObject();
    ObjectDesc o;
    const std::string mesh = n.child("mesh").string();
    o.mesh = resolve(sceneFile, mesh);
    o.name = n.has("name") ? n.child("name").string() : o.mesh.filename().string();
    Node medium = n.child("medium");
    o.medium = parseMedium(medium, sceneFile, units);
    if (n.has("surface")) o.surface = parseSurface(n.child("surface"));
    o.samples = resolve(sceneFile, n.child("samples").string());
    if (n.has("transform")) o.transform = parseTransform(n.child("transform"));
    n.rejectUnknownKeys();
    Fingerprint fp;
    fp.addFile(o.mesh);
    for (const auto& b : o.medium.blockers) fp.addFile(b);
    if (o.medium.density.type == DensityDesc::Type::Grid) fp.addFile(o.medium.density.file);
    // The samples do not depend on the boundary's index of refraction (each
    // method refracts at draw time), nor on the albedo or g (they hold the
    // attenuation and each Gaussian's weight; the albedo and the phase function
    // are taken at draw time): one sample file serves every ior, albedo and g.
    Json hashed = medium.json();
    if (hashed.is_object())
        for (const char* drawn : {"ior", "albedo", "g"}) hashed.erase(drawn);
    fp.addText(hashed.dump());
    if (medium.json().contains("preset"))
        fp.addText("units " + units.name);  // the preset's coefficients depend on them
    o.fingerprint = fp.value();
    return o;
}

RenderDesc parseRender(Node n) {
    n.requireObject();
    RenderDesc r;
    if (n.has("method")) {
        // Any name: the method table (methods/method_table.h) knows which are built
        // and rejects the others when the scene is rendered.
        r.method = n.child("method").string();
    }
    if (n.has("surface")) r.surface = n.child("surface").boolean();
    if (n.has("background")) r.background = n.child("background").boolean();
    n.rejectUnknownKeys();
    return r;
}

}  // namespace

glm::dvec4 spotCoefficients(const Light& light) {
    if (!light.spot) return glm::dvec4(0.0, 0.0, 0.0, 1.0);
    const double cosInner = std::cos(glm::radians(light.spot->innerDegrees));
    const double cosOuter = std::cos(glm::radians(light.spot->outerDegrees));
    const double scale = 1.0 / std::max(0.001, cosInner - cosOuter);
    return glm::dvec4(scale * light.spot->axis, -cosOuter * scale);
}

double spotFalloff(const Light& light, const Vec3& w) {
    if (!light.spot) return 1.0;
    const glm::dvec4 c = spotCoefficients(light);
    const double ramp = std::clamp(glm::dot(Vec3(c), w) + c.w, 0.0, 1.0);
    return ramp * ramp;
}

SceneDesc parseSceneText(const std::string& text, const std::filesystem::path& file) {
    const std::string name = file.string();
    const Json json = parseStrictJson(text, name);
    Node root(json, "", name);
    root.requireObject();
    SceneDesc scene;
    scene.file = file;
    Units units;
    if (root.has("units")) {
        Node u = root.child("units");
        units.name = u.string();
        units.millimetres = millimetresPerUnit(units.name);
        if (!units.millimetres) u.fail("unknown unit '" + units.name + "' (valid: mm, cm, m)");
    }
    scene.units = units.name;
    scene.camera = parseCamera(root.child("camera"));
    Node lights = root.child("lights");
    if (lights.arraySize() > kMaxLights)
        lights.fail("holds " + std::to_string(lights.arraySize()) + " lights; at most " + std::to_string(kMaxLights) +
                    " are supported (docs/robustness.md)");
    for (size_t i = 0; i < lights.arraySize(); ++i) {
        Node light = lights.element(i);
        light.requireObject();
        if (light.has("type") && light.child("type").json().is_string() &&
            light.child("type").string() == "environment") {
            if (scene.environment) light.fail("a second environment light; a scene has at most one");
            scene.environment = parseEnvironment(light, file);
        } else {
            scene.lights.push_back(parseLight(light));
        }
    }
    if (scene.environment && scene.lights.size() > kMaxLights - kMaxEnvironmentLights)
        lights.fail("holds " + std::to_string(scene.lights.size()) + " lights beside an environment; at most " +
                    std::to_string(kMaxLights - kMaxEnvironmentLights) +
                    " are supported with one, which is drawn as up to " + std::to_string(kMaxEnvironmentLights) +
                    " directional lights (docs/robustness.md)");
    Node objects = root.child("objects");
    if (objects.arraySize() == 0) objects.fail("must hold at least one object");
    for (size_t i = 0; i < objects.arraySize(); ++i)
        scene.objects.push_back(parseObject(objects.element(i), file, units));
    if (root.has("render")) scene.render = parseRender(root.child("render"));
    root.rejectUnknownKeys();
    return scene;
}

SceneDesc withoutTransforms(SceneDesc scene) {
    for (ObjectDesc& o : scene.objects) o.transform = Similarity{};
    return scene;
}

SceneDesc parseScene(const std::filesystem::path& file, const std::string& camera) {
    if (isGltfFile(file)) return importGltfScene(file, camera);
    if (!camera.empty())
        throw Error(file.string(), "a camera was named ('" + camera + "'), but only glTF files hold several cameras");
    return parseSceneText(readTextFile(file, "scene file"), file);
}

}  // namespace lucent
