#pragma once
// Private steps of the UV atlas (uv_atlas.h): segmentation, per-chart LSCM, overlap tests and
// packing. Plain data between them; Eigen stays inside uv_atlas_lscm.cpp.

#include <cstdint>
#include <span>
#include <vector>

#include "tissue/core/result.h"
#include "tissue/core/types.h"

namespace tissue::mesh::atlas {

/// Twice the signed area of the UV triangle (p, q, r), in double; positive counter-clockwise.
inline double uvCross(Float2 p, Float2 q, Float2 r) {
  return (double(q.x) - double(p.x)) * (double(r.y) - double(p.y)) -
         (double(q.y) - double(p.y)) * (double(r.x) - double(p.x));
}

/// Triangles across each edge: adjacent[3 * t + k] is the triangle across edge (k, k+1) of t,
/// or -1 on a mesh border.
std::vector<std::int32_t> triangleAdjacency(std::span<const Triangle> triangles, std::size_t vertexCount);

/// Region growing in a normal cone: chart index per triangle. A triangle joins the chart of an
/// edge neighbour when its normal is within `maxDeviationDeg` of the chart's seed normal.
std::vector<std::uint32_t> growCharts(std::span<const Float3> faceNormals,
                                      std::span<const std::int32_t> adjacency, float maxDeviationDeg);

/// A chart is disk-like when it is edge-connected, every vertex has 0 or 2 chart-border edges
/// (no pinched vertex), and V - E + F = 1 (one border loop, genus 0).
bool isDiskLike(std::span<const Triangle> triangles, std::span<const std::uint32_t> chartTriangles,
                std::span<const std::int32_t> adjacency);

/// Splits a chart in two halves across the median of its triangle centroids along their widest
/// axis; each half's edge-connected components become charts. Returns the new charts.
std::vector<std::vector<std::uint32_t>> splitChart(std::span<const Float3> positions,
                                                   std::span<const Triangle> triangles,
                                                   std::span<const std::uint32_t> chartTriangles,
                                                   std::span<const std::int32_t> adjacency);

/// Edge-connected components of a set of triangles.
std::vector<std::vector<std::uint32_t>> connectedParts(std::span<const std::uint32_t> chartTriangles,
                                                       std::span<const std::int32_t> adjacency,
                                                       std::size_t triangleCount);

/// One chart flattened: local vertices (chart-local index -> input vertex) and their UVs, in
/// mm (the conformal map scaled so its area equals the chart's 3D area).
struct FlatChart {
  std::vector<std::uint32_t> triangles;  ///< input triangle indices
  std::vector<std::uint32_t> vertices;   ///< input vertex of each local vertex
  std::vector<Triangle> localTriangles;  ///< local vertex indices, one per chart triangle
  std::vector<Float2> uv;                ///< mm, per local vertex
};

/// Least-squares conformal map of one chart (Lévy et al. 2002, eq. 8-9: the Cauchy-Riemann
/// residuals of each triangle, weighted by sqrt(area), with two border vertices pinned), solved
/// by Eigen's sparse Cholesky on the normal equations. Fails when the system is singular.
Result<FlatChart> flattenChart(std::span<const Float3> positions, std::span<const Triangle> triangles,
                               std::span<const std::uint32_t> chartTriangles);

/// True when every chart triangle has positive UV area and no two overlap.
bool isValidFlattening(const FlatChart& chart);

/// Places the charts (uv in mm) into [0, 1]^2: rotates each to its smallest bounding box, scales
/// all by one factor and packs them on shelves with `gutterTexels` between them at `resolution`.
/// Rewrites each chart's uv in place; returns the texels per mm.
float packCharts(std::vector<FlatChart>& charts, int resolution, float gutterTexels);

}  // namespace tissue::mesh::atlas
