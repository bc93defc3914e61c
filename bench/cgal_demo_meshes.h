#pragma once
// Meshes Lucent does not bundle, for honest measurement (issue 13): CGAL's demo
// data, read from the archive Debian's libcgal-demo installs, so that no mesh
// whose licence forbids it is redistributed here.
#include <filesystem>
#include <string>

namespace lucent {

inline const char* const kCgalDemoArchive = "/usr/share/doc/libcgal-dev/data.tar.gz";

// Extracts data/meshes/NAME.off from the archive into dir and returns its path.
// NAME is letters, digits, '-' and '_'. Throws Error naming the archive when it
// is missing (install libcgal-demo), malformed, or holds no such mesh.
std::filesystem::path extractCgalDemoMesh(const std::string& name, const std::filesystem::path& dir,
                                          const std::filesystem::path& archive = kCgalDemoArchive);

// Writes dir/NAME.json: the mesh seen from a camera that frames its bounding
// box, lit by one point light, filled with a medium of albedo 0.8 whose optical
// radius (sigma_t times the smallest half-extent of the box) is opticalRadius.
std::filesystem::path writeMeshScene(const std::filesystem::path& mesh, const std::filesystem::path& dir,
                                     double opticalRadius, int size);

}  // namespace lucent
