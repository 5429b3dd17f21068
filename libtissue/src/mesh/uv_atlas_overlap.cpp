// UV atlas: overlap tests of UV triangles (separating axis theorem on a uniform grid).
#include <algorithm>
#include <array>
#include <cmath>

#include "tissue/mesh/uv_atlas.h"
#include "uv_atlas_steps.h"

namespace tissue::mesh {
namespace {

using Tri2 = std::array<std::array<double, 2>, 3>;

/// Largest gap between the projections of `a` and `b` on the six edge normals (UV units): two
/// triangles have disjoint interiors exactly when some edge normal separates them (gap >= 0).
double separation(const Tri2& a, const Tri2& b) {
  double best = -1e300;
  for (const Tri2* t : {&a, &b}) {
    for (int e = 0; e < 3; ++e) {
      const auto& p = (*t)[e];
      const auto& q = (*t)[(e + 1) % 3];
      double nx = q[1] - p[1], ny = p[0] - q[0];
      const double len = std::hypot(nx, ny);
      if (len <= 0.0) continue;
      nx /= len, ny /= len;
      double aMin = 1e300, aMax = -1e300, bMin = 1e300, bMax = -1e300;
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

std::size_t countUvOverlaps(std::span<const Float2> uvs, std::span<const Triangle> triangles,
                            std::size_t maxCount) {
  if (triangles.empty()) return 0;
  // Step 1: the UV bounding box and a grid of about two triangles per cell.
  double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
  for (const Triangle& t : triangles)
    for (std::uint32_t v : t)
      lo[0] = std::min(lo[0], double(uvs[v].x)), lo[1] = std::min(lo[1], double(uvs[v].y)),
      hi[0] = std::max(hi[0], double(uvs[v].x)), hi[1] = std::max(hi[1], double(uvs[v].y));
  const double size = std::max({hi[0] - lo[0], hi[1] - lo[1], 1e-30});
  // Neighbours meet along shared edges at gap 0; rounding of float UVs may make it slightly
  // negative, so overlaps must exceed a millionth of the atlas size.
  const double touch = -1e-6 * size;
  const int grid = std::clamp(int(std::sqrt(double(triangles.size()) / 2.0)), 1, 512);
  const auto cell = [&](double x, int d) { return std::clamp(int((x - lo[d]) / size * grid), 0, grid - 1); };
  std::vector<Tri2> tris(triangles.size());
  std::vector<std::array<int, 4>> boxes(triangles.size());
  std::vector<std::vector<std::uint32_t>> cells(std::size_t(grid) * std::size_t(grid));
  for (std::size_t i = 0; i < triangles.size(); ++i) {
    double tlo[2] = {1e300, 1e300}, thi[2] = {-1e300, -1e300};
    for (int k = 0; k < 3; ++k) {
      const Float2 w = uvs[triangles[i][k]];
      tris[i][k] = {double(w.x), double(w.y)};
      for (int d = 0; d < 2; ++d)
        tlo[d] = std::min(tlo[d], tris[i][k][d]), thi[d] = std::max(thi[d], tris[i][k][d]);
    }
    boxes[i] = {cell(tlo[0], 0), cell(tlo[1], 1), cell(thi[0], 0), cell(thi[1], 1)};
    for (int y = boxes[i][1]; y <= boxes[i][3]; ++y)
      for (int x = boxes[i][0]; x <= boxes[i][2]; ++x)
        cells[std::size_t(y) * std::size_t(grid) + std::size_t(x)].push_back(std::uint32_t(i));
  }
  // Step 2: each candidate pair once, in the first cell both boxes share.
  std::size_t count = 0;
  for (int cy = 0; cy < grid; ++cy) {
    for (int cx = 0; cx < grid; ++cx) {
      const auto& c = cells[std::size_t(cy) * std::size_t(grid) + std::size_t(cx)];
      for (std::size_t a = 0; a < c.size(); ++a) {
        for (std::size_t b = a + 1; b < c.size(); ++b) {
          const std::uint32_t i = c[a], j = c[b];
          if (cx != std::max(boxes[i][0], boxes[j][0]) || cy != std::max(boxes[i][1], boxes[j][1])) continue;
          if (separation(tris[i], tris[j]) < touch && ++count >= maxCount) return count;
        }
      }
    }
  }
  return count;
}

bool hasUsableUvs(std::span<const Float2> uvs, std::span<const Triangle> triangles,
                  std::size_t positionCount) {
  if (uvs.empty() || uvs.size() != positionCount) return false;
  for (const Triangle& t : triangles) {
    for (std::uint32_t v : t)
      if (v >= uvs.size() || !std::isfinite(uvs[v].x) || !std::isfinite(uvs[v].y)) return false;
    // A triangle without UV area has no texels: its irradiance could not be stored.
    const Float2 p = uvs[t[0]], q = uvs[t[1]], r = uvs[t[2]];
    if (atlas::uvCross(p, q, r) == 0.0) return false;
  }
  return countUvOverlaps(uvs, triangles, 1) == 0;
}

namespace atlas {

bool isValidFlattening(const FlatChart& chart) {
  double total = 0.0;
  for (const Triangle& t : chart.localTriangles) {
    const Float2 p = chart.uv[t[0]], q = chart.uv[t[1]], r = chart.uv[t[2]];
    total += std::abs(uvCross(p, q, r));
  }
  // A flipped (or collapsed) triangle folds the chart; relative to the mean triangle area.
  const double minArea = 1e-9 * total / double(chart.localTriangles.size());
  for (const Triangle& t : chart.localTriangles) {
    const Float2 p = chart.uv[t[0]], q = chart.uv[t[1]], r = chart.uv[t[2]];
    if (uvCross(p, q, r) <= minArea) return false;
  }
  return countUvOverlaps(chart.uv, chart.localTriangles, 1) == 0;
}

}  // namespace atlas
}  // namespace tissue::mesh
