// UV atlas, step 2: least-squares conformal maps (Lévy, Petitjean, Ray and Maillot 2002).
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <cmath>
#include <unordered_map>

#include "uv_atlas_steps.h"
#include "vec3.h"

namespace tissue::mesh::atlas {

using namespace detail;

namespace {

/// A triangle in its own plane: corner 0 at the origin, corner 1 on +x, counter-clockwise.
struct PlanarTriangle {
  double x[3] = {}, y[3] = {};
  double area = 0.0;  ///< mm^2
};

PlanarTriangle planar(Float3 p0, Float3 p1, Float3 p2) {
  const Float3 e1 = p1 - p0, e2 = p2 - p0;
  const Float3 n = cross(e1, e2);
  const Float3 ax = normalizeOr(e1, Float3{1.0f, 0.0f, 0.0f});
  const Float3 ay = normalizeOr(cross(n, ax), Float3{0.0f, 1.0f, 0.0f});
  PlanarTriangle t;
  t.x[1] = dot(e1, ax);
  t.x[2] = dot(e2, ax);
  t.y[2] = dot(e2, ay);
  t.area = 0.5 * double(length(n));
  return t;
}

/// The two local vertices furthest apart (two sweeps of farthest-point search), pinned.
std::pair<std::uint32_t, std::uint32_t> pinPair(std::span<const Float3> positions,
                                                const std::vector<std::uint32_t>& vertices) {
  const auto farthest = [&](std::uint32_t from) {
    std::uint32_t best = from;
    float bestD = -1.0f;
    for (std::uint32_t i = 0; i < vertices.size(); ++i) {
      const Float3 d = positions[vertices[i]] - positions[vertices[from]];
      if (dot(d, d) > bestD) bestD = dot(d, d), best = i;
    }
    return best;
  };
  const std::uint32_t a = farthest(0);
  return {a, farthest(a)};
}

}  // namespace

Result<FlatChart> flattenChart(std::span<const Float3> positions, std::span<const Triangle> triangles,
                               std::span<const std::uint32_t> chartTriangles) {
  FlatChart chart;
  chart.triangles.assign(chartTriangles.begin(), chartTriangles.end());
  // Step 1: chart-local vertices.
  std::unordered_map<std::uint32_t, std::uint32_t> local;
  for (std::uint32_t t : chartTriangles) {
    Triangle lt{};
    for (int k = 0; k < 3; ++k) {
      const auto [it, added] = local.try_emplace(triangles[t][k], std::uint32_t(chart.vertices.size()));
      if (added) chart.vertices.push_back(triangles[t][k]);
      lt[k] = it->second;
    }
    chart.localTriangles.push_back(lt);
  }
  const std::size_t n = chart.vertices.size();
  chart.uv.assign(n, Float2{});
  const auto [pinA, pinB] = pinPair(positions, chart.vertices);
  const double pinDistance = length(positions[chart.vertices[pinB]] - positions[chart.vertices[pinA]]);
  if (pinA == pinB || !(pinDistance > 0.0)) return Error{"uv atlas: a chart has no extent"};
  // Step 2: unknowns (u, v) of the free vertices; pins at (0, 0) and (|pA - pB|, 0).
  std::vector<std::int64_t> column(n, -1);
  std::int64_t free = 0;
  for (std::size_t i = 0; i < n; ++i)
    if (i != pinA && i != pinB) column[i] = free++;
  const double pinU[2] = {0.0, pinDistance};
  // Step 3: the Cauchy-Riemann residuals per triangle (LSCM eq. 8-9), weighted by sqrt(area):
  // du/dx - dv/dy = 0 and du/dy + dv/dx = 0, with grad(phi_j) = rot90(e_j) / (2A).
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(chart.localTriangles.size() * 12);
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(Eigen::Index(2 * chart.localTriangles.size()));
  double area3d = 0.0;
  for (std::size_t f = 0; f < chart.localTriangles.size(); ++f) {
    const Triangle& lt = chart.localTriangles[f];
    const PlanarTriangle q = planar(positions[chart.vertices[lt[0]]], positions[chart.vertices[lt[1]]],
                                    positions[chart.vertices[lt[2]]]);
    area3d += q.area;
    if (q.area <= 0.0) continue;
    const double s = std::sqrt(q.area), inv2A = 1.0 / (2.0 * q.area);
    const auto row = Eigen::Index(2 * f);
    for (int j = 0; j < 3; ++j) {
      const int a = (j + 1) % 3, b = (j + 2) % 3;
      const double gx = -(q.y[b] - q.y[a]) * inv2A * s, gy = (q.x[b] - q.x[a]) * inv2A * s;
      const std::uint32_t v = lt[j];
      if (column[v] >= 0) {
        const auto cu = Eigen::Index(2 * column[v]), cv = cu + 1;
        entries.emplace_back(row, cu, gx);
        entries.emplace_back(row, cv, -gy);
        entries.emplace_back(row + 1, cu, gy);
        entries.emplace_back(row + 1, cv, gx);
      } else {  // pinned: (u, 0) moves to the right-hand side
        const double u = pinU[v == pinA ? 0 : 1];
        rhs[row] -= gx * u;
        rhs[row + 1] -= gy * u;
      }
    }
  }
  // Step 4: normal equations A^T A x = A^T b by sparse Cholesky (LDL^T).
  Eigen::SparseMatrix<double> a(Eigen::Index(2 * chart.localTriangles.size()), Eigen::Index(2 * free));
  a.setFromTriplets(entries.begin(), entries.end());
  const Eigen::SparseMatrix<double> ata = (a.transpose() * a).pruned();
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(ata);
  if (solver.info() != Eigen::Success) return Error{"uv atlas: singular LSCM system"};
  const Eigen::VectorXd x = solver.solve(a.transpose() * rhs);
  if (solver.info() != Eigen::Success || !x.allFinite()) return Error{"uv atlas: LSCM solve failed"};
  // Step 5: UVs in mm, scaled so that the flat area equals the 3D area.
  for (std::size_t i = 0; i < n; ++i) {
    if (column[i] >= 0)
      chart.uv[i] = {float(x[2 * column[i]]), float(x[2 * column[i] + 1])};
    else
      chart.uv[i] = {float(pinU[i == pinA ? 0 : 1]), 0.0f};
  }
  double areaUv = 0.0;
  for (const Triangle& lt : chart.localTriangles) {
    const Float2 p = chart.uv[lt[0]], q = chart.uv[lt[1]], r = chart.uv[lt[2]];
    areaUv += 0.5 * uvCross(p, q, r);
  }
  if (areaUv > 0.0) {
    const float scale = float(std::sqrt(area3d / areaUv));
    for (Float2& w : chart.uv)
      w = {w.x * scale, w.y * scale};
  }
  return chart;
}

}  // namespace tissue::mesh::atlas
