#pragma once
// Inside test of regular-grid cell centres against a closed triangle surface. Private to sim.

#include <array>
#include <span>
#include <vector>

#include "tissue/core/types.h"
#include "tissue/sim/vec3.h"

namespace tissue::sim::detail {

/// A regular grid: `cells` cells of edge `h` (mm) from `origin` (mm).
struct Grid {
  Vec3d origin;
  double h = 1.0;
  std::array<int, 3> cells{};
  std::size_t cellIndex(int i, int j, int k) const {
    return static_cast<std::size_t>(i) +
           static_cast<std::size_t>(cells[0]) *
               (static_cast<std::size_t>(j) +
                static_cast<std::size_t>(cells[1]) * static_cast<std::size_t>(k));
  }
  std::size_t cellCount() const {
    return static_cast<std::size_t>(cells[0]) * static_cast<std::size_t>(cells[1]) *
           static_cast<std::size_t>(cells[2]);
  }
};

/// inside[cellIndex] = 1 when the cell's centre is inside the closed surface: the number of
/// surface crossings of a ray from the centre along +x is odd. The ray is shifted off the
/// centre by a few 1e-6 h in y and z so that it does not pass exactly through mesh edges or
/// vertices on grid lines (a symmetric mesh often has them there).
std::vector<char> classifyCellCentres(const Grid& grid, std::span<const Float3> positions,
                                      std::span<const Triangle> triangles);

}  // namespace tissue::sim::detail
