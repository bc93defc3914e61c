#pragma once
// The problem file of `lucent transport` (docs/transport.md): a box of cells,
// boundary conditions per face, box regions of constant medium and isotropic
// volumetric source, and the points where the scalar flux is wanted. It lets a
// user check the discrete ordinates solver against the standard transport
// benchmarks, away from meshes, lights and cameras.
#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "core/math.h"

namespace lucent {

struct TransportRegion {
    Bounds3 box;
    double sigmaT = 0, sigmaS = 0, g = 0;
    double source = 0;  // isotropic, particles per unit volume per unit time
};

struct TransportProblem {
    std::filesystem::path file;
    Bounds3 domain;
    std::array<int, 3> cells{0, 0, 0};
    std::array<bool, 6> reflective{};      // x-, x+, y-, y+, z-, z+; false: vacuum
    std::vector<TransportRegion> regions;  // a later region overrides an earlier one
    std::vector<Vec3> points;
    // solver
    int directions = 48;
    int bands = 4;  // spherical-harmonic bands of the scattering source (M = bands^2 moments)
    int maxIterations = 500;
    double tolerance = 1e-5;
    // How the uncollided flux of the sources is found (docs/transport.md, Ray
    // effects): integrated cell to cell (marched), or swept along the N
    // directions with the rest; auto marches wherever it can.
    enum class Uncollided { Auto, Marched, Swept };
    Uncollided uncollided = Uncollided::Auto;
};

// Throws Error("FILE: /path: problem") for anything malformed or out of range.
TransportProblem parseTransportProblem(const std::filesystem::path& file);
TransportProblem parseTransportProblemText(const std::string& text, const std::filesystem::path& file);

}  // namespace lucent
