#pragma once
// The scene file of DESIGN.md, parsed strictly: every key known, every value of
// the right type and range, every error naming the file and the JSON path.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/math.h"
#include "core/similarity.h"

namespace lucent {

struct Camera {
    Vec3 position{0, 0, 5}, target{0, 0, 0}, up{0, 1, 0};
    double fovYDegrees = 40.0;
    int width = 512, height = 512;
};

// A spot light's cone, as KHR_lights_punctual defines it: full intensity within
// the inner angle of the axis, none beyond the outer one, and between them the
// square of a ramp linear in the cosine (spotFalloff).
struct SpotCone {
    Vec3 axis{0, 0, -1};         // unit direction the spot points in
    double innerDegrees = 0.0;   // [0, outerDegrees)
    double outerDegrees = 45.0;  // (innerDegrees, 90]
};

// A spot light is a point light with a cone: every method treats it as a point
// light whose intensity spotFalloff scales along each direction it sends light.
struct Light {
    enum class Type { Point, Directional };
    Type type = Type::Point;
    Vec3 position{0};              // point lights
    Vec3 direction{0};             // directional lights: unit direction the light travels in
    Rgb power{0};                  // intensity (W/sr) for point lights, irradiance (W/m^2) for directional
    std::optional<SpotCone> spot;  // point lights only
    // Point lights without a cone: a sphere of this radius around position that
    // emits uniformly from its surface with the same total power (core/sphere_light.h); 0: a point.
    double radius = 0.0;
};

// The cone's falloff as one affine step, (axis / (cos inner - cos outer),
// -cos outer / (cos inner - cos outer)), so that falloff = clamp(c.xyz . w + c.w, 0, 1)^2
// for w the unit direction the light travels; (0, 0, 0, 1) (falloff 1) without a
// cone. The shaders and kernels take these four numbers (KHR_lights_punctual's
// lightAngleScale and lightAngleOffset, with its floor of 0.001 on the difference).
glm::dvec4 spotCoefficients(const Light& light);
// The share of a point light's intensity it sends along the unit direction w (1 without a cone).
double spotFalloff(const Light& light, const Vec3& w);

struct SurfaceDesc {
    Rgb diffuse{0.8}, specular{0.1};
    double shininess = 32.0;
};

struct DensityDesc {
    enum class Type { Constant, Layers, Grid };
    Type type = Type::Constant;
    int axis = 0;                // layers
    std::vector<double> values;  // layers
    std::filesystem::path file;  // grid
    std::string gridName;        // grid, .vdb
    int dims[3] = {0, 0, 0};     // grid, raw
    Bounds3 bounds;              // grid, raw
};

struct MediumDesc {
    Rgb sigmaT{1.0}, albedo{0.5};
    double g = 0.0, ior = 1.0;
    DensityDesc density;
    std::vector<std::filesystem::path> blockers;
};

struct ObjectDesc {
    std::string name;
    std::filesystem::path mesh;
    int gltfNode = -1;  // with a glTF mesh file: the node whose mesh this is (core/gltf_scene.h)
    MediumDesc medium;
    std::optional<SurfaceDesc> surface;
    std::filesystem::path samples;
    Similarity transform;      // object to world; not part of the fingerprint (the sample file records its scale)
    uint64_t fingerprint = 0;  // of the mesh, blocker and grid bytes and the medium: ties a sample file to it
};

struct RenderDesc {
    std::string method = "auto";
    bool surface = true;
    // Whether the environment reaches the camera unscattered: behind the
    // objects, through them (attenuated) and reflected off a refracting
    // boundary. false: only the light the media scatter, and the surface term.
    bool background = false;
};

// The scene's environment light (core/environment_map.h holds the map's convention).
struct EnvironmentDesc {
    std::filesystem::path file;  // equirectangular .hdr or .exr
    double scale = 1.0;          // multiplies the map's radiance
    glm::dmat3 rotation{1.0};    // the map's directions to the world's
};

struct SceneDesc {
    std::filesystem::path file;
    std::string units;  // "mm", "cm", "m", or empty: lengths and coefficients per scene unit
    Camera camera;
    std::vector<Light> lights;                   // point, spot and directional
    std::optional<EnvironmentDesc> environment;  // at most one
    std::vector<ObjectDesc> objects;
    RenderDesc render;
    std::vector<std::string> warnings;  // what an imported file (glTF) had that Lucent does not map
};

// Throws Error("FILE: /json/path: problem"). Paths inside are made relative to the scene file.
// A .gltf or .glb file is imported (core/gltf_scene.h), looking through camera
// (a camera's name; empty: the file's first).
SceneDesc parseScene(const std::filesystem::path& file, const std::string& camera = {});
SceneDesc parseSceneText(const std::string& text, const std::filesystem::path& file);

// The scene with every object in its own space and at scale 1.
SceneDesc withoutTransforms(SceneDesc scene);

}  // namespace lucent
