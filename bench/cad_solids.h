#pragma once
// Solids from a solid modeller, for honest measurement (issue 40): OpenSCAD
// models (models/cad/*.scad) exported to closed STL meshes by Debian's openscad.
// The project commits the .scad sources, never the meshes they make.
#include <filesystem>

namespace lucent {

// Exports the OpenSCAD model scad to dir/<its stem>.stl with `openscad -o`
// (no shell) and returns that path. The mesh appears whole or not at all.
// Throws Error naming the model when it is not a regular .scad file, when
// openscad is missing (scripts/install-deps.sh installs it) or fails (its
// messages are in dir/<stem>.openscad.log).
std::filesystem::path exportScadSolid(const std::filesystem::path& scad, const std::filesystem::path& dir);

}  // namespace lucent
