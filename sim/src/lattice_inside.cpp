// Closed-surface check and the inside test of cell centres (ray parity with a jitter).
#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "lattice_inside.h"
#include "tissue/sim/lattice.h"

namespace tissue::sim {

Result<void> checkClosedSurface(std::size_t vertexCount, std::span<const Triangle> triangles) {
  if (triangles.empty()) return Error{"surface: no triangles; an embedded lattice needs a closed surface"};
  std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
  edges.reserve(3 * triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const Triangle& tri = triangles[t];
    for (int c = 0; c < 3; ++c) {
      if (tri[c] >= vertexCount)
        return Error{"surface: triangle " + std::to_string(t + 1) + " refers to vertex " +
                     std::to_string(tri[c] + 1) + " of " + std::to_string(vertexCount) + " (1-based)"};
      if (tri[c] == tri[(c + 1) % 3])
        return Error{"surface: triangle " + std::to_string(t + 1) + " repeats vertex " +
                     std::to_string(tri[c] + 1) + " (1-based); remove degenerate triangles"};
    }
    for (int c = 0; c < 3; ++c) {
      const std::uint32_t a = tri[c], b = tri[(c + 1) % 3];
      edges.emplace_back(std::min(a, b), std::max(a, b));
    }
  }
  std::sort(edges.begin(), edges.end());
  // Every edge of a closed 2-manifold belongs to exactly two triangles.
  std::size_t open = 0, nonManifold = 0;
  std::pair<std::uint32_t, std::uint32_t> firstOpen{}, firstNonManifold{};
  for (std::size_t k = 0; k < edges.size();) {
    std::size_t end = k + 1;
    while (end < edges.size() && edges[end] == edges[k])
      ++end;
    if (end - k == 1 && open++ == 0) firstOpen = edges[k];
    if (end - k > 2 && nonManifold++ == 0) firstNonManifold = edges[k];
    k = end;
  }
  auto edgeName = [](std::pair<std::uint32_t, std::uint32_t> e) {
    return "the edge between vertices " + std::to_string(e.first + 1) + " and " +
           std::to_string(e.second + 1) + " (1-based)";
  };
  if (nonManifold > 0)
    return Error{"surface is non-manifold: " + edgeName(firstNonManifold) +
                 " belongs to more than two triangles (" + std::to_string(nonManifold) +
                 " such edges); an embedded lattice needs a closed 2-manifold"};
  if (open > 0)
    return Error{"surface is open: " + edgeName(firstOpen) + " belongs to one triangle (" +
                 std::to_string(open) +
                 " boundary edges); close the holes, pass geometric vertices (not render vertices split at "
                 "UV seams), or use surface springs for an open patch"};
  return {};
}

namespace detail {
namespace {

/// x of the crossing of the line {y = py, z = pz} with triangle (a, b, c), if the line passes
/// through the triangle's (y, z) projection (2D barycentrics by edge functions).
bool crossing(const Float3& af, const Float3& bf, const Float3& cf, double py, double pz, double& x) {
  const Vec3d a{af.x, af.y, af.z}, b{bf.x, bf.y, bf.z}, c{cf.x, cf.y, cf.z};
  auto edge = [&](const Vec3d& p, const Vec3d& q) {
    return (q.y - p.y) * (pz - p.z) - (q.z - p.z) * (py - p.y);
  };
  const double wa = edge(b, c), wb = edge(c, a), wc = edge(a, b);
  const bool allPos = wa >= 0 && wb >= 0 && wc >= 0, allNeg = wa <= 0 && wb <= 0 && wc <= 0;
  const double sum = wa + wb + wc;
  if (!(allPos || allNeg) || sum == 0.0) return false;
  x = (wa * a.x + wb * b.x + wc * c.x) / sum;
  return true;
}

}  // namespace

std::vector<char> classifyCellCentres(const Grid& grid, std::span<const Float3> positions,
                                      std::span<const Triangle> triangles) {
  const int ny = grid.cells[1], nz = grid.cells[2];
  const double jitterY = 1.2345678e-6 * grid.h, jitterZ = 2.7182818e-6 * grid.h;
  auto rayY = [&](int j) { return grid.origin.y + (j + 0.5) * grid.h + jitterY; };
  auto rayZ = [&](int k) { return grid.origin.z + (k + 0.5) * grid.h + jitterZ; };

  // Bin each triangle into the columns (j, k) whose ray passes through its (y, z) bounding box.
  std::vector<std::vector<std::uint32_t>> columns(static_cast<std::size_t>(ny) *
                                                  static_cast<std::size_t>(nz));
  auto column = [&](double v, double o, int n, bool upper) {
    const double f = (v - o) / grid.h - 0.5;
    const int idx = upper ? static_cast<int>(std::floor(f)) : static_cast<int>(std::ceil(f));
    return std::clamp(idx, upper ? -1 : 0, upper ? n - 1 : n);
  };
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const Float3 &a = positions[triangles[t][0]], &b = positions[triangles[t][1]],
                 &c = positions[triangles[t][2]];
    const double oy = grid.origin.y + jitterY, oz = grid.origin.z + jitterZ;
    const int j0 = column(std::min({a.y, b.y, c.y}), oy, ny, false);
    const int j1 = column(std::max({a.y, b.y, c.y}), oy, ny, true);
    const int k0 = column(std::min({a.z, b.z, c.z}), oz, nz, false);
    const int k1 = column(std::max({a.z, b.z, c.z}), oz, nz, true);
    for (int k = k0; k <= k1; ++k)
      for (int j = j0; j <= j1; ++j)
        columns[static_cast<std::size_t>(j) + static_cast<std::size_t>(ny) * static_cast<std::size_t>(k)]
            .push_back(static_cast<std::uint32_t>(t));
  }

  // Per column: sorted crossings; a centre is inside when an odd number lie beyond it.
  std::vector<char> inside(grid.cellCount(), 0);
  std::vector<double> xs;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j) {
      xs.clear();
      for (std::uint32_t t : columns[static_cast<std::size_t>(j) +
                                     static_cast<std::size_t>(ny) * static_cast<std::size_t>(k)]) {
        double x = 0.0;
        const Triangle& tri = triangles[t];
        if (crossing(positions[tri[0]], positions[tri[1]], positions[tri[2]], rayY(j), rayZ(k), x))
          xs.push_back(x);
      }
      std::sort(xs.begin(), xs.end());
      for (int i = 0; i < grid.cells[0]; ++i) {
        const double xc = grid.origin.x + (i + 0.5) * grid.h;
        const auto beyond = xs.end() - std::upper_bound(xs.begin(), xs.end(), xc);
        inside[grid.cellIndex(i, j, k)] = (beyond % 2) == 1;
      }
    }
  return inside;
}

}  // namespace detail
}  // namespace tissue::sim
