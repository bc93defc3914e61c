#include "hybrid/internal/unfolded_medium.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace lucent::hybrid {

UnfoldedMedium::UnfoldedMedium(const DomGrid& grid, const std::array<bool, 6>& reflective) : grid_(grid) {
    for (int a = 0; a < 3; ++a) {
        if (reflective[2 * a] && reflective[2 * a + 1])
            throw std::invalid_argument("UnfoldedMedium: both faces of an axis are reflective");
        lo_[a] = reflective[2 * a] ? -grid.dims[a] : 0;
        hi_[a] = reflective[2 * a + 1] ? 2 * grid.dims[a] : grid.dims[a];
        bricks_[a] = (hi_[a] - lo_[a] + kBrick - 1) / kBrick;
    }
    const size_t stride[3] = {1, size_t(grid.dims[0]), size_t(grid.dims[0]) * size_t(grid.dims[1])};
    const size_t brickStride[3] = {1, size_t(bricks_[0]), size_t(bricks_[0]) * size_t(bricks_[1])};
    for (int a = 0; a < 3; ++a)
        for (int c = lo_[a]; c < hi_[a]; ++c) {
            const int folded = c < 0 ? -1 - c : c >= grid.dims[a] ? 2 * grid.dims[a] - 1 - c : c;
            cell_[a].push_back(size_t(folded) * stride[a]);
            brickPart_[a].push_back(size_t((c - lo_[a]) / kBrick) * brickStride[a]);
        }
    brick_.assign(size_t(bricks_[0]) * bricks_[1] * bricks_[2], glm::vec4(0.0f));
    for (int bz = 0; bz < bricks_[2]; ++bz)
        for (int by = 0; by < bricks_[1]; ++by)
            for (int bx = 0; bx < bricks_[0]; ++bx) {
                const Cell b{bx, by, bz};
                Cell first{}, end{};
                for (int a = 0; a < 3; ++a) {
                    first[a] = lo_[a] + b[a] * kBrick;
                    end[a] = std::min(first[a] + kBrick, hi_[a]);
                }
                const glm::vec4 sigma = grid.extinction[grid.index()(fold(first))];
                bool alike = true;
                for (int z = first[2]; z < end[2] && alike; ++z)
                    for (int y = first[1]; y < end[1] && alike; ++y)
                        for (int x = first[0]; x < end[0] && alike; ++x)
                            alike = glm::vec3(grid.extinction[grid.index()(fold({x, y, z}))]) == glm::vec3(sigma);
                // A brick cut short by the lattice's end is not skipped: its box is not kBrick wide.
                for (int a = 0; a < 3; ++a) alike = alike && end[a] - first[a] == kBrick;
                brick_[bx + size_t(bricks_[0]) * (by + size_t(bricks_[1]) * bz)] =
                    alike ? glm::vec4(glm::vec3(sigma), 1.0f) : glm::vec4(0.0f);
            }
}

UnfoldedMedium::Cell UnfoldedMedium::fold(Cell c) const {
    for (int a = 0; a < 3; ++a) {
        c[a] = std::clamp(c[a], lo_[a], hi_[a] - 1);
        if (c[a] < 0) c[a] = -1 - c[a];
        if (c[a] >= grid_.dims[a]) c[a] = 2 * grid_.dims[a] - 1 - c[a];
    }
    return c;
}

glm::dvec3 UnfoldedMedium::extinction(const Cell& c) const {
    return glm::dvec3(glm::vec3(grid_.extinction[inside(c) ? indexOf(c) : grid_.index()(fold(c))]));
}

glm::dvec3 UnfoldedMedium::opticalDepth(const glm::dvec3& a, const glm::dvec3& b, bool* uniform) const {
    const glm::dvec3 dir = b - a;
    const double length = glm::length(dir * grid_.edges);
    Cell c{int(std::floor(a.x)), int(std::floor(a.y)), int(std::floor(a.z))};
    const Cell last{int(std::floor(b.x)), int(std::floor(b.y)), int(std::floor(b.z))};
    int step[3];
    double next[3], delta[3];
    // The parameter at which the segment leaves cell c on each axis.
    auto restart = [&](double t) {
        for (int k = 0; k < 3; ++k) {
            step[k] = dir[k] > 0.0 ? 1 : -1;
            delta[k] = dir[k] != 0.0 ? 1.0 / std::abs(dir[k]) : kInfinity;  // of the segment, per cell
            next[k] = dir[k] != 0.0 ? ((dir[k] > 0.0 ? c[k] + 1 : c[k]) - a[k]) / dir[k] : kInfinity;
            next[k] = std::max(next[k], t);
        }
    };
    restart(0.0);
    const glm::dvec3 first = extinction(c);
    glm::dvec3 tau(0.0);
    double t = 0.0;
    while (true) {
        const glm::vec4& brick = brickOf(c);
        if (brick.w > 0.0f) {
            // Across the whole brick in one step: to where the segment leaves its box.
            double exit = 1.0;
            int axis = -1, bound = 0;
            for (int k = 0; k < 3; ++k) {
                if (dir[k] == 0.0) continue;
                const int base = lo_[k] + (c[k] - lo_[k]) / kBrick * kBrick;
                const int plane = dir[k] > 0.0 ? base + kBrick : base;
                const double at = (plane - a[k]) / dir[k];
                if (at < exit) {
                    exit = at;
                    axis = k;
                    bound = plane;
                }
            }
            const glm::dvec3 sigma = glm::dvec3(glm::vec3(brick));
            if (uniform && sigma != first) *uniform = false;
            tau += sigma * ((std::max(exit, t) - t) * length);
            if (axis < 0) break;
            t = std::max(exit, t);
            const glm::dvec3 p = a + dir * t;
            // The cell the segment is in just past p, never behind the one it
            // left on any axis (rounding must not step back: it would loop).
            for (int k = 0; k < 3; ++k)
                c[k] = dir[k] < 0.0 ? std::min(c[k], int(std::ceil(p[k])) - 1) : std::max(c[k], int(std::floor(p[k])));
            c[axis] = dir[axis] > 0.0 ? bound : bound - 1;  // into the next brick, whatever the rounding
            restart(t);
            continue;
        }
        const int k = next[0] <= next[1] && next[0] <= next[2] ? 0 : next[1] <= next[2] ? 1 : 2;
        const double end = std::min(next[k], 1.0);
        const glm::dvec3 sigma = extinction(c);
        if (uniform && sigma != first) *uniform = false;
        tau += sigma * ((end - t) * length);
        if (end >= 1.0 || c == last) break;
        t = end;
        c[k] += step[k];
        next[k] += delta[k];
    }
    return tau;
}

}  // namespace lucent::hybrid
