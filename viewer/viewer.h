#pragma once
// `lucent view`: a GLFW window showing the scene through the ScatteringRenderer,
// with a Dear ImGui panel to move the camera and edit lights live.
#include <filesystem>
#include <string>

#include "core/scene.h"

namespace lucent {

struct ViewerOptions {
    std::filesystem::path script;      // commands run one per frame (docs/viewer.md)
    std::filesystem::path screenshot;  // saved after the script, then the viewer exits
    int width = 0, height = 0;         // window size (0: the scene camera's)
};

void runViewer(const SceneDesc& scene, const ViewerOptions& options);

}  // namespace lucent
