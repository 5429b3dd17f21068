#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "tissue/mesh/local_planes.h"
#include "vec3.h"

namespace tissue::mesh {

using namespace detail;

namespace {

/// Uniform grid of cell size `cell` over the points: the sphere query visits 27 cells.
class PointGrid {
 public:
  PointGrid(std::span<const Float3> points, float cell) : m_cell(cell) {
    for (std::uint32_t i = 0; i < points.size(); ++i)
      m_cells[key(cellOf(points[i]))].push_back(i);
  }
  template <class F>
  void forEachNear(Float3 p, F&& f) const {
    const auto c = cellOf(p);
    for (int dz = -1; dz <= 1; ++dz)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          auto it = m_cells.find(key({c[0] + dx, c[1] + dy, c[2] + dz}));
          if (it == m_cells.end()) continue;
          for (auto j : it->second)
            f(j);
        }
  }

 private:
  std::array<std::int64_t, 3> cellOf(Float3 p) const {
    return {std::int64_t(std::floor(p.x / m_cell)), std::int64_t(std::floor(p.y / m_cell)),
            std::int64_t(std::floor(p.z / m_cell))};
  }
  static std::uint64_t key(std::array<std::int64_t, 3> c) {
    return (std::uint64_t(c[0] & 0x1FFFFF) << 42) | (std::uint64_t(c[1] & 0x1FFFFF) << 21) |
           std::uint64_t(c[2] & 0x1FFFFF);
  }
  float m_cell;
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> m_cells;
};

}  // namespace

Neighbourhoods findNeighbourhoods(std::span<const Float3> positions, float radiusMm,
                                  std::span<const Triangle> oneRingOf) {
  // Step 1: 1-ring adjacency (both directions of every triangle edge).
  std::vector<std::vector<std::uint32_t>> lists(positions.size());
  for (const auto& t : oneRingOf)
    for (int k = 0; k < 3; ++k) {
      lists[t[k]].push_back(t[(k + 1) % 3]);
      lists[t[(k + 1) % 3]].push_back(t[k]);
    }
  // Step 2: the sphere of radius r (François eq. 8) around each vertex, in these positions.
  if (radiusMm > 0.0f && std::isfinite(radiusMm)) {
    const PointGrid grid(positions, radiusMm);
    const float r2 = radiusMm * radiusMm;
    for (std::uint32_t i = 0; i < positions.size(); ++i) {
      grid.forEachNear(positions[i], [&](std::uint32_t j) {
        const Float3 d = positions[j] - positions[i];
        if (dot(d, d) <= r2) lists[i].push_back(j);
      });
    }
  }
  // Step 3: sorted, unique, self included; flattened.
  Neighbourhoods hoods;
  hoods.offsets.reserve(positions.size() + 1);
  hoods.offsets.push_back(0);
  for (std::uint32_t i = 0; i < positions.size(); ++i) {
    auto& l = lists[i];
    l.push_back(i);
    std::sort(l.begin(), l.end());
    l.erase(std::unique(l.begin(), l.end()), l.end());
    hoods.indices.insert(hoods.indices.end(), l.begin(), l.end());
    hoods.offsets.push_back(std::uint32_t(hoods.indices.size()));
    std::vector<std::uint32_t>().swap(l);
  }
  return hoods;
}

}  // namespace tissue::mesh
