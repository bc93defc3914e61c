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

struct Light {
    enum class Type { Point, Directional };
    Type type = Type::Point;
    Vec3 position{0};   // point lights
    Vec3 direction{0};  // directional lights: unit direction the light travels in
    Rgb power{0};       // intensity (W/sr) for point lights, irradiance (W/m^2) for directional
};

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
    MediumDesc medium;
    std::optional<SurfaceDesc> surface;
    std::filesystem::path samples;
    Similarity transform;      // object to world; not part of the fingerprint (the sample file records its scale)
    uint64_t fingerprint = 0;  // of the mesh, blocker and grid bytes and the medium: ties a sample file to it
};

struct RenderDesc {
    std::string method = "auto";
    bool surface = true;
};

struct SceneDesc {
    std::filesystem::path file;
    std::string units;  // "mm", "cm", "m", or empty: lengths and coefficients per scene unit
    Camera camera;
    std::vector<Light> lights;
    std::vector<ObjectDesc> objects;
    RenderDesc render;
};

// Throws Error("FILE: /json/path: problem"). Paths inside are made relative to the scene file.
SceneDesc parseScene(const std::filesystem::path& file);
SceneDesc parseSceneText(const std::string& text, const std::filesystem::path& file);

// The scene with every object in its own space and at scale 1.
SceneDesc withoutTransforms(SceneDesc scene);

}  // namespace lucent
