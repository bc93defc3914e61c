#pragma once
// The extinction of a DomGrid as its sources' mirror images see it: the
// lattice of cells unfolded across the reflective faces (cell i's image across
// the low face of an axis lies at -1 - i, across the high face at 2 n - 1 - i),
// and optical depths traced through it. A reflective face returns the light
// that reaches it as if it came from the mirror image of its source through
// the mirrored medium, so the uncollided flux of the images is that of
// straight lines through this lattice. The tracing crosses a brick of
// kBrick^3 cells in one step where the brick is uniform: the far field of
// hybrid/internal/uncollided_flux.cpp spends most of its time here.
#include <array>
#include <vector>

#include <glm/glm.hpp>

#include "hybrid/internal/dom_solver.h"

namespace lucent::hybrid {

class UnfoldedMedium {
public:
    using Cell = std::array<int, 3>;
    static constexpr int kBrick = 4;

    // At most one reflective face per axis (x-, x+, y-, y+, z-, z+).
    UnfoldedMedium(const DomGrid& grid, const std::array<bool, 6>& reflective);

    // The grid's cell that unfolded cell c mirrors (c itself inside the grid).
    Cell fold(Cell c) const;
    glm::dvec3 extinction(const Cell& c) const;
    // The optical depth (rgb) between points a and b given in cells (cell c
    // spans [c, c + 1) on each axis), every cell between them crossed for its
    // own length (Amanatides and Woo's traversal). `uniform`, when given, is
    // cleared where the cells crossed differ in extinction.
    glm::dvec3 opticalDepth(const glm::dvec3& a, const glm::dvec3& b, bool* uniform = nullptr) const;

private:
    const DomGrid& grid_;
    Cell lo_{}, hi_{};                              // the unfolded lattice's cells: lo up to hi, hi excluded
    Cell bricks_{};                                 // bricks per axis, from lo
    std::array<std::vector<size_t>, 3> cell_;       // per axis, from lo: the folded cell's part of its grid index
    std::array<std::vector<size_t>, 3> brickPart_;  // per axis, from lo: the brick's part of its index
    std::vector<glm::vec4> brick_;                  // a uniform brick's extinction, w 1; w 0 where its cells differ
    bool inside(const Cell& c) const {
        return c[0] >= lo_[0] && c[1] >= lo_[1] && c[2] >= lo_[2] && c[0] < hi_[0] && c[1] < hi_[1] && c[2] < hi_[2];
    }
    size_t indexOf(const Cell& c) const {  // c inside
        return cell_[0][size_t(c[0] - lo_[0])] + cell_[1][size_t(c[1] - lo_[1])] + cell_[2][size_t(c[2] - lo_[2])];
    }
    const glm::vec4& brickOf(const Cell& c) const {
        static const glm::vec4 none(0.0f);
        if (!inside(c)) return none;
        return brick_[brickPart_[0][size_t(c[0] - lo_[0])] + brickPart_[1][size_t(c[1] - lo_[1])] +
                      brickPart_[2][size_t(c[2] - lo_[2])]];
    }
};

}  // namespace lucent::hybrid
