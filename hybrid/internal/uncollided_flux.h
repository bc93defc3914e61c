#pragma once
// The uncollided flux of volumetric sources, integrated cell to cell instead
// of swept. Swept along N discrete directions, the light of a small source
// reaches only the cells those directions pass through (ray effects, the
// classic failure of discrete ordinates; docs/transport.md). The classic cure
// is the first-collision source: compute the uncollided flux analytically,
// scatter it once, and sweep only what has collided, which is spread out and
// smooth. Here each cell gathers from every source cell:
//   - near (within kNearCells cells on every axis), the exact average over both
//     cells of e^{-sigma r} / (4 pi r^2) Y_lm(direction), with sigma the
//     extinction along the centres' segment (the medium taken as uniform over
//     so short a path);
//   - far, the point kernel q V e^{-tau} / (4 pi r^2) Y_lm with the optical
//     depth tau traced through the cells between the centres, corrected to
//     the two cells' average to second order in the cells' size over r.
// Vacuum all round: a reflective face would need the sources' mirror images.
#include <cstddef>
#include <vector>

#include <glm/glm.hpp>

#include "hybrid/internal/dom_solver.h"

namespace lucent::hybrid {

constexpr int kNearCells = 3;

// The traversal steps the far field costs: cells times source cells times the
// mean path across the grid in cells; what the caller weighs against its budget.
double uncollidedFluxWork(const DomGrid& grid, size_t sourceCells);

// The uncollided flux moments phi_lm = int L(omega) Y_lm(omega) d omega (rgb),
// averaged over each cell, [cell][bands^2], of the isotropic volumetric source
// density `source` (per cell, particles per unit volume per unit time) through
// the grid's extinction (rgb). Cells with no extinction are vacuum.
std::vector<glm::vec4> uncollidedFlux(const DomGrid& grid, const std::vector<double>& source, int bands);

}  // namespace lucent::hybrid
