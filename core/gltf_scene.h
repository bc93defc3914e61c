#pragma once
// glTF 2.0 assets (.gltf with its buffers, or .glb) as Lucent scenes: every
// node with a mesh becomes an object, its material a medium, KHR_lights_punctual
// lights become lights, and a camera the camera. docs/gltf.md is the mapping
// table (glTF property, Lucent key, units, what is dropped).
#include <filesystem>
#include <string>
#include <vector>

#include "core/scene.h"
#include "core/triangle_mesh.h"

namespace lucent {

// .gltf or .glb, by extension (any case).
bool isGltfFile(const std::filesystem::path& file);

// The scene of a glTF file. camera: the name of the camera node (or camera) to
// look through; empty: the first camera of the scene, or one that frames every
// object when the file has none. What cannot be mapped is one line each in
// SceneDesc::warnings; what cannot be drawn at all is an Error("FILE: problem").
SceneDesc importGltfScene(const std::filesystem::path& file, const std::string& camera = {});

// The boundary of node's mesh (every primitive, vertices welded within 1e-6 of
// the mesh's size), in the space ObjectDesc::transform places: the node's own
// when its world matrix is a similarity, the scene's otherwise; checked closed
// as every mesh is (loadClosedMesh).
TriangleMesh loadGltfMesh(const std::filesystem::path& file, int node, std::vector<std::string>& warnings);

// KHR_materials_volume_scatter's multiscatterColor (the albedo of the whole
// medium) to the single-scattering albedo, channel by channel: the inverse of
// the published approximation rho_ms = (1 - s)(1 - 0.139 s) / (1 + 1.17 s) with
// s = sqrt((1 - rho_ss) / (1 - g rho_ss)) (OpenPBR and KHR_materials_volume_scatter).
double singleScatteringAlbedo(double multiscatter, double g);

}  // namespace lucent
