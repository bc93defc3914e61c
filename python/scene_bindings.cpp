// lucent.Scene and its parts as Python objects: what a scene file (or a glTF
// asset) describes, editable in place. Every setter checks what the scene
// parser checks (core/scene.cpp), so Python cannot make a scene the command
// line would refuse.
#include <pybind11/stl.h>
#include <pybind11/stl_bind.h>

#include <string>

#include "core/error.h"
#include "core/fingerprint.h"
#include "core/limits.h"
#include "core/scene.h"
#include "python/bindings.h"
#include "python/vector_caster.h"

PYBIND11_MAKE_OPAQUE(std::vector<lucent::Light>)
PYBIND11_MAKE_OPAQUE(std::vector<lucent::ObjectDesc>)

namespace lucent::python {
namespace {

namespace py = pybind11;

double inRange(double x, double lo, double hi, const char* what) {
    if (!(x >= lo && x <= hi))
        throw py::value_error(std::string(what) + " must lie in [" + std::to_string(lo) + ", " + std::to_string(hi) +
                              "]");
    return x;
}

Vec3 inRange(const Vec3& v, double lo, double hi, const char* what) {
    for (int i = 0; i < 3; ++i) inRange(v[i], lo, hi, what);
    return v;
}

Vec3 unit(const Vec3& v, const char* what) {
    const double length = glm::length(v);
    if (!(length > 0.0) || !std::isfinite(length)) throw py::value_error(std::string(what) + " must not be zero");
    return v / length;
}

void bindCamera(py::module_& m) {
    py::class_<Camera>(m, "Camera", "Where the image is seen from (docs/scene-file.md, \"camera\")")
        .def_property(
            "position", [](const Camera& c) { return c.position; },
            [](Camera& c, const Vec3& v) { c.position = inRange(v, -kMaxCoordinate, kMaxCoordinate, "position"); })
        .def_property(
            "target", [](const Camera& c) { return c.target; },
            [](Camera& c, const Vec3& v) { c.target = inRange(v, -kMaxCoordinate, kMaxCoordinate, "target"); })
        .def_property(
            "up", [](const Camera& c) { return c.up; }, [](Camera& c, const Vec3& v) { c.up = unit(v, "up"); })
        .def_property(
            "fov_y", [](const Camera& c) { return c.fovYDegrees; },
            [](Camera& c, double v) { c.fovYDegrees = inRange(v, 1e-3, 179.0, "fov_y"); }, "degrees")
        .def_property(
            "width", [](const Camera& c) { return c.width; },
            [](Camera& c, int v) { c.width = int(inRange(v, 1, 16384, "width")); })
        .def_property(
            "height", [](const Camera& c) { return c.height; },
            [](Camera& c, int v) { c.height = int(inRange(v, 1, 16384, "height")); });
}

void bindLight(py::module_& m) {
    py::class_<Light>(m, "Light", "A point, spot or directional light (docs/scene-file.md, \"lights\")")
        .def(py::init([](const std::string& type, const Vec3& position, const Vec3& direction, const Vec3& power) {
                 Light l;
                 if (type == "directional") {
                     l.type = Light::Type::Directional;
                     l.direction = unit(direction, "direction");
                 } else if (type == "point") {
                     l.position = inRange(position, -kMaxCoordinate, kMaxCoordinate, "position");
                 } else {
                     throw py::value_error("type must be 'point' or 'directional' (a spot comes from a scene file)");
                 }
                 l.power = inRange(power, 0.0, kMaxMagnitude, "intensity");
                 return l;
             }),
             py::arg("type") = "point", py::arg("position") = Vec3(0.0), py::arg("direction") = Vec3(0, -1, 0),
             py::arg("intensity") = Vec3(1.0),
             "intensity: W/sr per channel for a point light, W/m^2 (irradiance) for a directional one")
        .def_property_readonly(
            "type",
            [](const Light& l) {
                return l.type == Light::Type::Directional ? "directional" : l.spot ? "spot" : "point";
            })
        .def_property(
            "position", [](const Light& l) { return l.position; },
            [](Light& l, const Vec3& v) { l.position = inRange(v, -kMaxCoordinate, kMaxCoordinate, "position"); })
        .def_property(
            "direction",
            [](const Light& l) {
                return l.type == Light::Type::Directional ? l.direction : l.spot ? l.spot->axis : Vec3(0.0);
            },
            [](Light& l, const Vec3& v) {
                if (l.type == Light::Type::Directional)
                    l.direction = unit(v, "direction");
                else if (l.spot)
                    l.spot->axis = unit(v, "direction");
                else
                    throw py::value_error("a point light has no direction");
            })
        .def_property(
            "intensity", [](const Light& l) { return l.power; },
            [](Light& l, const Vec3& v) { l.power = inRange(v, 0.0, kMaxMagnitude, "intensity"); })
        .def_property(
            "radius", [](const Light& l) { return l.radius; },
            [](Light& l, double r) {
                if (l.type != Light::Type::Point || l.spot) throw py::value_error("only a point light has a radius");
                l.radius = inRange(r, 0.0, kMaxCoordinate, "radius");
            });
    py::bind_vector<std::vector<Light>>(m, "LightList");
}

// Extinction decides the samples: a new sigma_t gives the object a new
// fingerprint, so that a sample file made for the old one is refused (run
// lucent.preprocess again) instead of drawing the old medium.
void setSigmaT(ObjectDesc& o, const Vec3& sigmaT) {
    o.medium.sigmaT = inRange(sigmaT, 0.0, kMaxMagnitude, "sigma_t");
    Fingerprint fp;
    fp.addBytes(&o.fingerprint, sizeof o.fingerprint);
    fp.addText("sigma_t set from Python");
    fp.addBytes(&o.medium.sigmaT, sizeof o.medium.sigmaT);
    o.fingerprint = fp.value();
}

void bindObject(py::module_& m) {
    py::class_<ObjectDesc>(m, "Object", "A translucent object: its mesh, medium and sample file")
        .def_property_readonly("name", [](const ObjectDesc& o) { return o.name; })
        .def_property_readonly("mesh", [](const ObjectDesc& o) { return o.mesh.string(); })
        .def_property(
            "samples", [](const ObjectDesc& o) { return o.samples.string(); },
            [](ObjectDesc& o, const std::string& path) {
                if (path.empty()) throw py::value_error("samples must name a file");
                o.samples = path;
            },
            "the sample file lucent.preprocess writes and the sample methods read")
        .def_property(
            "sigma_t", [](const ObjectDesc& o) { return o.medium.sigmaT; }, &setSigmaT,
            "extinction per scene unit and channel; changing it asks for lucent.preprocess again")
        .def_property(
            "albedo", [](const ObjectDesc& o) { return o.medium.albedo; },
            [](ObjectDesc& o, const Vec3& v) { o.medium.albedo = inRange(v, 0.0, 1.0, "albedo"); })
        .def_property(
            "g", [](const ObjectDesc& o) { return o.medium.g; },
            [](ObjectDesc& o, double g) { o.medium.g = inRange(g, -0.999, 0.999, "g"); })
        .def_property(
            "ior", [](const ObjectDesc& o) { return o.medium.ior; },
            [](ObjectDesc& o, double n) { o.medium.ior = inRange(n, 1.0, 4.0, "ior"); })
        .def_property_readonly("scale", [](const ObjectDesc& o) { return o.transform.scale; })
        .def_property_readonly("translation", [](const ObjectDesc& o) { return o.transform.translation; });
    py::bind_vector<std::vector<ObjectDesc>>(m, "ObjectList");
}

void bindScene(py::module_& m) {
    py::class_<SceneDesc>(m, "Scene", "A scene as lucent.load_scene read it; edit it in place, then render it")
        .def_property_readonly("file", [](const SceneDesc& s) { return s.file.string(); })
        .def_readonly("warnings", &SceneDesc::warnings, "what an imported glTF had that Lucent does not map")
        .def_property_readonly(
            "camera", [](SceneDesc& s) -> Camera& { return s.camera; }, py::return_value_policy::reference_internal)
        .def_property_readonly(
            "lights", [](SceneDesc& s) -> std::vector<Light>& { return s.lights; },
            py::return_value_policy::reference_internal)
        .def_property_readonly(
            "objects", [](SceneDesc& s) -> std::vector<ObjectDesc>& { return s.objects; },
            py::return_value_policy::reference_internal)
        .def_property(
            "method", [](const SceneDesc& s) { return s.render.method; },
            [](SceneDesc& s, const std::string& method) { s.render.method = method; },
            "the method lucent.render uses when given none ('auto' picks one)")
        .def("__copy__", [](const SceneDesc& s) { return SceneDesc(s); })
        .def("__deepcopy__", [](const SceneDesc& s, py::dict) { return SceneDesc(s); });
    m.def(
        "load_scene", [](const std::string& path, const std::string& camera) { return parseScene(path, camera); },
        py::arg("path"), py::arg("camera") = "",
        "Reads a scene file (JSON) or a glTF 2.0 asset (.gltf, .glb); camera names a glTF camera. Raises lucent.Error "
        "with the command line's one-line message.");
}

}  // namespace

void bindSceneTypes(py::module_& m) {
    bindCamera(m);
    bindLight(m);
    bindObject(m);
    bindScene(m);
}

}  // namespace lucent::python
