#pragma once
// The uncollided flux of volumetric sources, integrated cell to cell instead
// of swept. Swept along N discrete directions, the light of a small source
// reaches only the cells those directions pass through (ray effects, the
// classic failure of discrete ordinates; docs/transport.md). The classic cure
// is the first-collision source: compute the uncollided flux analytically,
// scatter it once, and sweep only what has collided, which is spread out and
// smooth. Here each cell gathers from every source cell:
//   - near (within kNearCells cells on every axis), the exact average over both
//     cells of e^{-sigma r} / (4 pi r^2) Y_lm(direction), with sigma the mean
//     extinction along the centres' segment; where the cells between differ,
//     scaled by how much more light point pairs traced through them carry
//     than through the mean (a control variate of 2^3 x 2^3 pairs);
//   - far, the point kernel q e^{-tau} / (4 pi r^2) Y_lm from Gauss points
//     of the source, tau traced through the cells, corrected to the target
//     cell's average to second order in its size over r. Source cells that
//     emit alike are gathered into boxes (a k-d tree) and seen as one from
//     three box lengths away, while the attenuation across a box stays under
//     one optical depth: a distant target traces a few boxes, not every cell.
// A reflective face holds its sources' mirror images (at most one reflective
// face per axis: two would mirror the images without end), whose light
// crosses the mirrored medium (hybrid/internal/unfolded_medium.h).
#include <array>
#include <cstddef>
#include <vector>

#include <glm/glm.hpp>

#include "hybrid/internal/dom_solver.h"

namespace lucent::hybrid {

constexpr int kNearCells = 3;
// The most source cells, their mirror images counted, the uncollided flux is
// integrated for: each takes a cell of the source list and the tree over it,
// about 200 bytes in all (400 MB here).
constexpr size_t kMostMarchedSources = size_t(1) << 21;

// The mirror images of each source cell, itself included, with the reflective
// faces x-, x+, y-, y+, z-, z+: 1, 2, 4 or 8; 0 when both faces of an axis are
// reflective.
int mirrorImages(const std::array<bool, 6>& reflective);

// An upper bound on the traversal steps the far field costs for the source
// density `source` (per cell): the points it traces, counted, times half the
// grid's summed dimensions; what the caller weighs against its budget.
// Infinite where both faces of an axis are reflective. The caller keeps the
// source cells and their images within kMostMarchedSources.
double uncollidedFluxWork(const DomGrid& grid, const std::vector<double>& source,
                          const std::array<bool, 6>& reflective);

// The uncollided flux moments phi_lm = int L(omega) Y_lm(omega) d omega (rgb),
// averaged over each cell, [cell][bands^2], of the isotropic volumetric source
// density `source` (per cell, particles per unit volume per unit time) through
// the grid's extinction (rgb), with the faces `reflective` marks mirrors
// (x-, x+, y-, y+, z-, z+; mirrorImages must not be 0). Cells with no
// extinction are vacuum.
std::vector<glm::vec4> uncollidedFlux(const DomGrid& grid, const std::vector<double>& source, int bands,
                                      const std::array<bool, 6>& reflective);
// The same in the cells [lo, hi) only (one rank's share of the grid), [cell of
// the box][bands^2], the box's cells in the grid's order.
std::vector<glm::vec4> uncollidedFlux(const DomGrid& grid, const std::vector<double>& source, int bands,
                                      const std::array<bool, 6>& reflective, const std::array<int, 3>& lo,
                                      const std::array<int, 3>& hi);

}  // namespace lucent::hybrid
