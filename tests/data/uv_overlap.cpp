#include "uv_overlap.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

namespace tissue::datatest {
namespace {

using Tri2 = std::array<std::array<double, 2>, 3>;

/// Largest gap between the projections of `a` and `b` over the six edge normals (UV units).
double separation(const Tri2& a, const Tri2& b) {
  double best = -1e30;
  for (const Tri2* t : {&a, &b}) {
    for (int e = 0; e < 3; ++e) {
      const auto& p = (*t)[e];
      const auto& q = (*t)[(e + 1) % 3];
      double nx = q[1] - p[1], ny = p[0] - q[0];
      const double len = std::hypot(nx, ny);
      if (len <= 0.0) continue;
      nx /= len;
      ny /= len;
      double aMin = 1e30, aMax = -1e30, bMin = 1e30, bMax = -1e30;
      for (int k = 0; k < 3; ++k) {
        const double pa = a[k][0] * nx + a[k][1] * ny, pb = b[k][0] * nx + b[k][1] * ny;
        aMin = std::min(aMin, pa), aMax = std::max(aMax, pa);
        bMin = std::min(bMin, pb), bMax = std::max(bMax, pb);
      }
      best = std::max(best, std::max(bMin - aMax, aMin - bMax));
    }
  }
  return best;
}

}  // namespace

std::vector<int> uvCharts(const std::vector<Triangle>& uvTriangles, std::size_t uvCount) {
  std::vector<std::size_t> parent(uvCount);
  std::iota(parent.begin(), parent.end(), std::size_t(0));
  const auto find = [&parent](std::size_t i) {
    while (parent[i] != i)
      i = parent[i] = parent[parent[i]];
    return i;
  };
  for (const Triangle& t : uvTriangles) {
    parent[find(t[1])] = find(t[0]);
    parent[find(t[2])] = find(t[0]);
  }
  std::vector<int> chart(uvTriangles.size());
  for (std::size_t i = 0; i < uvTriangles.size(); ++i)
    chart[i] = int(find(uvTriangles[i][0]));
  return chart;
}

std::vector<UvConflict> findUvConflicts(const std::vector<Float2>& uvs,
                                        const std::vector<Triangle>& uvTriangles, double gutter,
                                        std::size_t maxConflicts) {
  // Same-chart neighbours touch along edges (gap 0); a tiny tolerance absorbs rounding.
  constexpr double kTouch = -1e-9;
  constexpr int kGrid = 256;
  const std::vector<int> chart = uvCharts(uvTriangles, uvs.size());
  std::vector<Tri2> tris(uvTriangles.size());
  std::vector<std::array<int, 4>> boxes(uvTriangles.size());  // x0, y0, x1, y1 cells
  std::vector<std::vector<std::size_t>> cells(std::size_t(kGrid) * kGrid);
  const auto cellOf = [](double x) { return std::clamp(int(std::floor(x * kGrid)), 0, kGrid - 1); };
  for (std::size_t i = 0; i < uvTriangles.size(); ++i) {
    double lo[2] = {1e30, 1e30}, hi[2] = {-1e30, -1e30};
    for (int k = 0; k < 3; ++k) {
      const Float2& t = uvs[uvTriangles[i][k]];
      tris[i][k] = {double(t.x), double(t.y)};
      for (int d = 0; d < 2; ++d)
        lo[d] = std::min(lo[d], tris[i][k][d]), hi[d] = std::max(hi[d], tris[i][k][d]);
    }
    boxes[i] = {cellOf(lo[0] - gutter), cellOf(lo[1] - gutter), cellOf(hi[0] + gutter),
                cellOf(hi[1] + gutter)};
    for (int y = boxes[i][1]; y <= boxes[i][3]; ++y)
      for (int x = boxes[i][0]; x <= boxes[i][2]; ++x)
        cells[std::size_t(y) * kGrid + x].push_back(i);
  }
  std::vector<UvConflict> conflicts;
  for (int cy = 0; cy < kGrid; ++cy) {
    for (int cx = 0; cx < kGrid; ++cx) {
      const auto& cell = cells[std::size_t(cy) * kGrid + cx];
      for (std::size_t a = 0; a < cell.size(); ++a) {
        for (std::size_t b = a + 1; b < cell.size(); ++b) {
          const std::size_t i = cell[a], j = cell[b];
          // Test each pair once: in the first cell both expanded boxes share.
          if (cx != std::max(boxes[i][0], boxes[j][0]) || cy != std::max(boxes[i][1], boxes[j][1])) continue;
          const double gap = separation(tris[i], tris[j]);
          const double required = chart[i] == chart[j] ? kTouch : gutter;
          if (gap < required) conflicts.push_back({i, j, gap});
          if (conflicts.size() >= maxConflicts) return conflicts;
        }
      }
    }
  }
  return conflicts;
}

}  // namespace tissue::datatest
