// Uniaxial compression and Hertz indentation of an elastic block (see indentation.h).
#include "tissue/sim/indentation.h"

#include <Eigen/Dense>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <string>

#include "linear_stiffness.h"

namespace tissue::sim {

Result<UniaxialResult> measureUniaxial(const ElasticBlockConfig& config, double strain) {
  if (!(strain > 0.0 && strain < 0.5)) return Error{"uniaxial: the strain must be in (0, 0.5)"};
  auto block = buildElasticBlock(config);
  if (!block) return block.error();
  const auto [nx, ny, nz] = block->cells;
  const double h = block->cellSizeMm, height = nz * h;
  // Rollers: bottom z = 0 and top z = -strain * height, x and y free; one bottom corner held in x
  // and y and the next corner along x in y remove the rigid motions without a lateral constraint
  // (a clamped face would measure a constrained modulus, larger than E).
  std::vector<DofConstraint> constraints;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      constraints.push_back({std::uint32_t(block->node(i, j, 0)), 2, 0.0});
      constraints.push_back({std::uint32_t(block->node(i, j, nz)), 2, -strain * height});
    }
  constraints.push_back({std::uint32_t(block->node(0, 0, 0)), 0, 0.0});
  constraints.push_back({std::uint32_t(block->node(0, 0, 0)), 1, 0.0});
  constraints.push_back({std::uint32_t(block->node(nx, 0, 0)), 1, 0.0});
  auto solved =
      solveLinearStatic(block->springs, block->positions, constraints, gridEliminationOrder(block->cells));
  if (!solved) return solved.error();
  UniaxialResult out;
  for (std::size_t c = 0; c < constraints.size(); ++c)
    if (constraints[c].axis == 2 && constraints[c].displacementMm != 0.0) out.forceN -= solved->reactionN[c];
  const double area = nx * h * ny * h;                         // mm^2
  out.effectiveModulusKpa = out.forceN / area / strain * 1e3;  // N/mm^2 -> kPa
  out.modulusRatio = out.effectiveModulusKpa / config.material.youngsModulusKpa;
  // Lateral strain: mean x displacement of the x = W face minus that of the x = 0 face, over W.
  double dx = 0.0;
  int count = 0;
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j, ++count)
      dx += solved->displacement[block->node(nx, j, k)].x - solved->displacement[block->node(0, j, k)].x;
  out.poissonRatio = dx / count / (nx * h) / strain;
  return out;
}

Result<std::vector<IndentationPoint>> indentSphere(const IndentationConfig& config) {
  const double radius = config.sphereRadiusMm;
  if (!(radius > 0.0) || !std::isfinite(radius))
    return Error{"indentation: the radius must be positive (mm)"};
  std::vector<double> depths = config.depthsMm;
  if (depths.empty()) depths = {0.05 * radius, 0.1 * radius, 0.15 * radius, 0.2 * radius};
  for (double d : depths)
    if (!(d > 0.0 && d < radius)) return Error{"indentation: each depth must be in (0, R) mm"};
  auto block = buildElasticBlock(config.block);
  if (!block) return block.error();
  const auto [nx, ny, nz] = block->cells;
  const double h = block->cellSizeMm;

  // Supports: bottom on rollers (z), symmetry planes x = 0 (x held) and y = 0 (y held).
  const std::size_t n = block->positions.size();
  std::vector<char> held(3 * n, 0);
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i) {
        const std::size_t v = block->node(i, j, k);
        if (k == 0) held[3 * v + 2] = 1;
        if (i == 0) held[3 * v + 0] = 1;
        if (j == 0) held[3 * v + 1] = 1;
      }
  const std::vector<std::uint32_t> order = detail::nestedDissectionOrder(block->cells);
  const detail::FreeSystem sys = detail::assembleFree(block->springs, block->positions, held, order);
  Eigen::SimplicialLDLT<detail::SparseMatrix, Eigen::Lower, Eigen::NaturalOrdering<int>> solver(sys.k);
  if (solver.info() != Eigen::Success) return Error{"indentation: the block's stiffness matrix is singular"};

  // Candidate contact nodes: top nodes within 1.3 contact radii of the deepest depth (plus a cell).
  const double deepest = *std::max_element(depths.begin(), depths.end());
  const double reach = 1.3 * std::sqrt(radius * deepest) + 1.5 * h;
  std::vector<std::size_t> candidates;
  std::vector<double> r;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      const double rr = h * std::hypot(double(i), double(j));
      if (rr > reach) continue;
      candidates.push_back(block->node(i, j, nz));
      r.push_back(rr);
    }
  if (reach > std::min(nx, ny) * h)
    return Error{"indentation: the quarter block (" + std::to_string(std::min(nx, ny) * h) +
                 " mm wide) is narrower than the contact zone (" + std::to_string(reach) + " mm)"};
  // Compliance S (mm/N): S(c, d) = downward displacement of candidate c under 1 N down at d.
  const int m = static_cast<int>(candidates.size());
  Eigen::MatrixXd s(m, m);
  for (int d = 0; d < m; ++d) {
    Eigen::VectorXd f = Eigen::VectorXd::Zero(sys.k.rows());
    f[sys.freeIndex[3 * candidates[d] + 2]] = -1.0;
    const Eigen::VectorXd u = solver.solve(f);
    for (int c = 0; c < m; ++c)
      s(c, d) = -u[sys.freeIndex[3 * candidates[c] + 2]];
  }

  std::vector<IndentationPoint> out;
  for (double depth : depths) {
    // Gap demand: the sphere's surface lies delta_c below the top face at candidate c.
    Eigen::VectorXd delta(m);
    for (int c = 0; c < m; ++c)
      delta[c] = r[c] < radius ? depth - (radius - std::sqrt(radius * radius - r[c] * r[c])) : -radius;
    // Signorini by an active set: p >= 0, w = S p >= delta, p (w - delta) = 0.
    std::vector<char> active(m);
    for (int c = 0; c < m; ++c)
      active[c] = delta[c] > 0.0;
    Eigen::VectorXd p = Eigen::VectorXd::Zero(m);
    for (int iteration = 0; iteration < 4 * m + 10; ++iteration) {
      std::vector<int> a;
      for (int c = 0; c < m; ++c)
        if (active[c]) a.push_back(c);
      p.setZero();
      if (!a.empty()) {
        Eigen::MatrixXd saa(a.size(), a.size());
        Eigen::VectorXd da(a.size());
        for (std::size_t x = 0; x < a.size(); ++x) {
          da[Eigen::Index(x)] = delta[a[x]];
          for (std::size_t y = 0; y < a.size(); ++y)
            saa(Eigen::Index(x), Eigen::Index(y)) = s(a[x], a[y]);
        }
        const Eigen::VectorXd pa = saa.ldlt().solve(da);
        for (std::size_t x = 0; x < a.size(); ++x)
          p[a[x]] = pa[Eigen::Index(x)];
      }
      bool changed = false;
      for (int c = 0; c < m; ++c)  // release nodes the sphere would have to pull
        if (active[c] && p[c] < 0.0) {
          active[c] = 0;
          changed = true;
        }
      if (changed) continue;
      const Eigen::VectorXd w = s * p;
      for (int c = 0; c < m; ++c)  // add nodes that would penetrate the sphere
        if (!active[c] && w[c] < delta[c] - 1e-12 * radius) {
          active[c] = 1;
          changed = true;
        }
      if (!changed) break;
    }
    IndentationPoint point;
    point.depthMm = depth;
    for (int c = 0; c < m; ++c)
      if (active[c]) {
        point.forceN += p[c];
        point.contactRadiusMm = std::max(point.contactRadiusMm, r[c]);
        ++point.contactNodes;
      }
    if (point.contactRadiusMm + 1.5 * h > reach)
      return Error{"indentation: the contact reached the edge of the candidate zone"};
    point.forceN *= 4.0;  // the quarter model carries a quarter of the load
    point.hertzN =
        hertzForceN(config.block.material.youngsModulusKpa, config.poissonRatioForHertz, radius, depth);
    out.push_back(point);
  }
  return out;
}

}  // namespace tissue::sim
