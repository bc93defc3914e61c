#pragma once
// Blender's Cycles as lucent-bench-peer's peer: one Blender process renders a
// Lucent scene's first object (a homogeneous medium behind an index-matched
// boundary) under its point lights, at each requested sample count and seed
// (bench/cycles/render_scene.py). Never needed by the tests.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "core/image.h"
#include "core/scene.h"
#include "core/triangle_mesh.h"

namespace lucent {

struct CyclesRender {
    std::string name;  // names the image, cycles-NAME.pfm
    int samples = 1;
    uint64_t seed = 1;
};

struct CyclesImage {
    CyclesRender render;
    double seconds = 0.0;  // Cycles' render call alone (the first, untimed render set it up)
    Image image;
};

struct CyclesScene {
    TriangleMesh mesh;  // in world space
    MediumDesc medium;
    std::vector<Light> lights;  // point lights
    Camera camera;
    int volumeBounces = 0;  // 0: single scattering; else the most scattering events a path takes
};

// Renders each of renders with blender in dir (its scene, images and log
// blender.log), on two threads. Error when Blender fails or writes no image.
std::vector<CyclesImage> renderWithCycles(const std::string& blender, const std::filesystem::path& dir,
                                          const CyclesScene& scene, const std::vector<CyclesRender>& renders);

}  // namespace lucent
