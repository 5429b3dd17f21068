// Linear statics of spring networks and elastic blocks (lattice or tets of a cubic grid), see
// indentation.h.
#include "tissue/sim/indentation.h"

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <string>

#include "linear_stiffness.h"
#include "tissue/sim/lattice.h"
#include "tissue/sim/tet_springs.h"
#include "tissue/sim/units.h"

namespace tissue::sim {
namespace {

using detail::FreeSystem;
using detail::SparseMatrix;
using detail::stiffnessTimes;

double& component(Vec3d& v, int axis) {
  return axis == 0 ? v.x : axis == 1 ? v.y : v.z;
}

/// Lattice of the box [0, n] (unit cells), scaled to cells of h mm, renumbered in grid order.
Result<ElasticBlock> latticeBlock(const ElasticBlockConfig& c) {
  const auto [nx, ny, nz] = c.cells;
  const float X = float(nx), Y = float(ny), Z = float(nz);
  const std::vector<Float3> box = {{0, 0, 0}, {X, 0, 0}, {0, Y, 0}, {X, Y, 0},
                                   {0, 0, Z}, {X, 0, Z}, {0, Y, Z}, {X, Y, Z}};
  const std::vector<Triangle> faces = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                                       {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  LatticeConfig lc;
  lc.cellSize = 1.0;
  auto lattice = buildEmbeddedLattice(box, faces, lc);
  if (!lattice) return lattice.error();
  if (lattice->cells.size() != std::size_t(nx) * ny * nz)
    return Error{"elastic block: the lattice kept " + std::to_string(lattice->cells.size()) + " of " +
                 std::to_string(nx * ny * nz) + " cells"};
  for (Vec3d& p : lattice->nodePositions)
    p = c.cellSizeMm * (p - lattice->origin);
  for (double& l : lattice->springs.restLength)
    l *= c.cellSizeMm;
  lattice->cellSize = c.cellSizeMm;
  if (auto ok = setLatticeStiffness(*lattice, c.material, c.latticeBoundary); !ok) return ok.error();

  ElasticBlock block;
  block.cells = c.cells;
  block.cellSizeMm = c.cellSizeMm;
  block.positions.resize(std::size_t(nx + 1) * (ny + 1) * (nz + 1));
  std::vector<std::uint32_t> gridOf(lattice->nodeCount());
  for (std::size_t n = 0; n < lattice->nodeCount(); ++n) {
    const Vec3d q = (1.0 / c.cellSizeMm) * lattice->nodePositions[n];
    const auto g = block.node(int(std::lround(q.x)), int(std::lround(q.y)), int(std::lround(q.z)));
    gridOf[n] = static_cast<std::uint32_t>(g);
  }
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i)
        block.positions[block.node(i, j, k)] = c.cellSizeMm * Vec3d{double(i), double(j), double(k)};
  const SpringNetwork& from = lattice->springs;
  for (std::size_t s = 0; s < from.size(); ++s)
    addSpring(block.springs, gridOf[from.i[s]], gridOf[from.j[s]], from.restLength[s],
              from.stiffness[s] / kStiffnessPerNewtonPerMm, 0.0);
  if (auto ok = finalizeSpringNetwork(block.springs, block.positions.size()); !ok) return ok.error();
  return block;
}

Result<ElasticBlock> tetBlock(const ElasticBlockConfig& c) {
  ElasticBlock block;
  block.cells = c.cells;
  block.cellSizeMm = c.cellSizeMm;
  const auto [nx, ny, nz] = c.cells;
  block.positions.resize(std::size_t(nx + 1) * (ny + 1) * (nz + 1));
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i)
        block.positions[block.node(i, j, k)] = c.cellSizeMm * Vec3d{double(i), double(j), double(k)};
  const std::vector<Tet> tets = gridTets(c.cells, c.split);
  std::vector<Float3> floats(block.positions.size());
  for (std::size_t n = 0; n < floats.size(); ++n)
    floats[n] = {float(block.positions[n].x), float(block.positions[n].y), float(block.positions[n].z)};
  auto springs = buildTetEdgeSprings(floats, tets, {});
  if (!springs) return springs.error();
  block.springs = std::move(*springs);
  if (auto ok = setTetEdgeStiffness(block.springs, block.positions, tets, c.material, c.tetFormula); !ok)
    return ok.error();
  return block;
}

}  // namespace

Result<LinearStaticResult> solveLinearStatic(const SpringNetwork& network, std::span<const Vec3d> rest,
                                             std::span<const DofConstraint> constraints,
                                             std::span<const std::uint32_t> vertexOrder) {
  if (!vertexOrder.empty() && vertexOrder.size() != rest.size())
    return Error{"linear static: the vertex order must list every vertex once"};
  const std::size_t n = rest.size();
  if (network.vertexCount() != n) return Error{"linear static: the network and the positions differ in size"};
  std::vector<char> held(3 * n, 0);
  LinearStaticResult out;
  out.displacement.assign(n, Vec3d{});
  for (const DofConstraint& c : constraints) {
    if (c.vertex >= n || c.axis < 0 || c.axis > 2)
      return Error{"linear static: constraint on vertex " + std::to_string(c.vertex) + " axis " +
                   std::to_string(c.axis) + " out of range"};
    char& h = held[3 * c.vertex + std::size_t(c.axis)];
    if (h) return Error{"linear static: vertex " + std::to_string(c.vertex) + " axis held twice"};
    h = 1;
    component(out.displacement[c.vertex], c.axis) = c.displacementMm;
  }
  const FreeSystem sys = detail::assembleFree(network, rest, held, vertexOrder);
  // Right-hand side: -K_fc u_c, i.e. minus the forces of the prescribed displacements on free DOFs.
  const std::vector<double> fc = stiffnessTimes(network, rest, out.displacement);
  Eigen::VectorXd rhs(sys.k.rows());
  for (std::size_t d = 0; d < held.size(); ++d)
    if (sys.freeIndex[d] >= 0) rhs[sys.freeIndex[d]] = -fc[d];
  Eigen::VectorXd u;
  bool ok = false;
  if (vertexOrder.empty()) {
    Eigen::SimplicialLDLT<SparseMatrix> solver(sys.k);
    ok = solver.info() == Eigen::Success && (solver.vectorD().array() > 0.0).all();
    if (ok) u = solver.solve(rhs);
  } else {
    Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower, Eigen::NaturalOrdering<int>> solver(sys.k);
    ok = solver.info() == Eigen::Success && (solver.vectorD().array() > 0.0).all();
    if (ok) u = solver.solve(rhs);
  }
  if (!ok) return Error{"linear static: the stiffness matrix is singular; hold more degrees of freedom"};
  for (std::size_t d = 0; d < held.size(); ++d)
    if (sys.freeIndex[d] >= 0) component(out.displacement[d / 3], int(d % 3)) = u[sys.freeIndex[d]];
  const std::vector<double> f = stiffnessTimes(network, rest, out.displacement);
  for (const DofConstraint& c : constraints)
    out.reactionN.push_back(f[3 * c.vertex + std::size_t(c.axis)]);
  return out;
}

std::vector<Tet> gridTets(std::array<int, 3> cells, CubeSplit split) {
  // Plain variables, not a structured binding: lambdas capturing bindings need C++20 support that
  // clang 14 (the fuzz and sanitizer trees' compiler) lacks.
  const int nx = cells[0], ny = cells[1], nz = cells[2];
  // Corners by bits: 1 = +x, 2 = +y, 4 = +z.
  static constexpr int kFiveEven[5][4] = {
      {1, 2, 4, 7}, {0, 1, 2, 4}, {3, 1, 2, 7}, {5, 1, 4, 7}, {6, 2, 4, 7}};
  static constexpr int kFiveOdd[5][4] = {
      {0, 3, 5, 6}, {1, 0, 3, 5}, {2, 0, 3, 6}, {4, 0, 5, 6}, {7, 3, 5, 6}};
  static constexpr int kSix[6][4] = {{0, 1, 3, 7}, {0, 1, 5, 7}, {0, 2, 3, 7},
                                     {0, 2, 6, 7}, {0, 4, 5, 7}, {0, 4, 6, 7}};
  std::vector<Tet> tets;
  auto nodeOf = [&](int i, int j, int k, int corner) {
    return static_cast<std::uint32_t>(
        (i + (corner & 1)) + (nx + 1) * ((j + ((corner >> 1) & 1)) + (ny + 1) * (k + (corner >> 2))));
  };
  auto add = [&](int i, int j, int k, const int(&t)[4]) {
    Tet tet{nodeOf(i, j, k, t[0]), nodeOf(i, j, k, t[1]), nodeOf(i, j, k, t[2]), nodeOf(i, j, k, t[3])};
    // Orientation: det of the corner offsets' bits.
    auto off = [](int c) { return Vec3d{double(c & 1), double((c >> 1) & 1), double(c >> 2)}; };
    const Vec3d a = off(t[1]) - off(t[0]), b = off(t[2]) - off(t[0]), d = off(t[3]) - off(t[0]);
    const double det =
        a.x * (b.y * d.z - b.z * d.y) - a.y * (b.x * d.z - b.z * d.x) + a.z * (b.x * d.y - b.y * d.x);
    if (det < 0.0) std::swap(tet[2], tet[3]);
    tets.push_back(tet);
  };
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        if (split == CubeSplit::Six) {
          for (const auto& t : kSix)
            add(i, j, k, t);
        } else {
          for (const auto& t : ((i + j + k) % 2 == 0 ? kFiveEven : kFiveOdd))
            add(i, j, k, t);
        }
      }
  return tets;
}

Result<ElasticBlock> buildElasticBlock(const ElasticBlockConfig& config) {
  for (int n : config.cells)
    if (n < 1 || n > 200) return Error{"elastic block: cells per axis must be in [1, 200]"};
  if (!(config.cellSizeMm > 0.0) || !std::isfinite(config.cellSizeMm))
    return Error{"elastic block: the cell size must be a positive number of mm"};
  if (auto ok = validateMaterial(config.material); !ok) return ok.error();
  return config.network == ElasticNetwork::Lattice ? latticeBlock(config) : tetBlock(config);
}

std::vector<std::uint32_t> gridEliminationOrder(std::array<int, 3> cells) {
  return detail::nestedDissectionOrder(cells);
}

double hertzForceN(double youngsModulusKpa, double poissonRatio, double radiusMm, double depthMm) {
  const double eStar = kpaToNewtonPerMm2(youngsModulusKpa) / (1.0 - poissonRatio * poissonRatio);
  return 4.0 / 3.0 * eStar * std::sqrt(radiusMm) * std::pow(depthMm, 1.5);
}

}  // namespace tissue::sim
