// buildEmbeddedLattice: grid, kept cells, nodes, springs, masses and the surface's weights.
#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "lattice_inside.h"
#include "tissue/sim/lattice.h"

namespace tissue::sim {
namespace {

constexpr std::size_t kMaxGridCells = 4'000'000;

/// The grid around the surface's bounding box, centred on it; `h` from the config.
Result<detail::Grid> makeGrid(std::span<const Float3> positions, const LatticeConfig& config) {
  Vec3d lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
  for (const Float3& p : positions) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      return Error{"lattice: a surface vertex has a non-finite coordinate"};
    lo = {std::min(lo.x, double(p.x)), std::min(lo.y, double(p.y)), std::min(lo.z, double(p.z))};
    hi = {std::max(hi.x, double(p.x)), std::max(hi.y, double(p.y)), std::max(hi.z, double(p.z))};
  }
  const Vec3d extent = hi - lo;
  const double longest = std::max({extent.x, extent.y, extent.z});
  if (!(longest > 0.0)) return Error{"lattice: the surface has no extent"};
  if (config.cellSize == 0.0 && config.cellsAlongLongestAxis < 1)
    return Error{
        "lattice: give a positive cell size (mm) or a positive number of cells along the longest axis"};
  const double h = config.cellSize > 0.0 ? config.cellSize : longest / config.cellsAlongLongestAxis;
  if (!(h > 0.0) || !std::isfinite(h)) return Error{"lattice: the cell size must be a positive number of mm"};
  detail::Grid grid;
  grid.h = h;
  const double e[3] = {extent.x, extent.y, extent.z};
  double size = 1.0;
  for (int a = 0; a < 3; ++a) {
    grid.cells[a] = std::max(1, static_cast<int>(std::ceil(e[a] / h - 1e-9)));
    size *= grid.cells[a];
  }
  if (size > double(kMaxGridCells))
    return Error{"lattice: cell size " + std::to_string(h) + " mm makes " + std::to_string(size) +
                 " grid cells (more than 4 million); use a larger cell size"};
  // Centre the grid on the box (each side's slack split evenly).
  grid.origin = {lo.x - 0.5 * (grid.cells[0] * h - extent.x), lo.y - 0.5 * (grid.cells[1] * h - extent.y),
                 lo.z - 0.5 * (grid.cells[2] * h - extent.z)};
  return grid;
}

/// The cell that contains `p` (clamped into the grid) and p's local coordinates in it, in [0,1].
std::array<int, 3> cellOf(const detail::Grid& grid, const Float3& p, Vec3d& local) {
  const Vec3d r = (1.0 / grid.h) * (Vec3d{p.x, p.y, p.z} - grid.origin);
  const double q[3] = {r.x, r.y, r.z};
  std::array<int, 3> c{};
  double t[3];
  for (int a = 0; a < 3; ++a) {
    c[a] = std::clamp(static_cast<int>(std::floor(q[a])), 0, grid.cells[a] - 1);
    t[a] = std::clamp(q[a] - c[a], 0.0, 1.0);
  }
  local = {t[0], t[1], t[2]};
  return c;
}

/// Trilinear weight of corner `corner` (bit 0 x, bit 1 y, bit 2 z) at local coordinates `t`.
double trilinear(int corner, const Vec3d& t) {
  return ((corner & 1) ? t.x : 1.0 - t.x) * ((corner & 2) ? t.y : 1.0 - t.y) *
         ((corner & 4) ? t.z : 1.0 - t.z);
}

/// One spring per pair of corners of every kept cell (edges, face and body diagonals), once.
Result<SpringNetwork> latticeSprings(const EmbeddedLattice& lattice, const SpringConfig& config) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
  pairs.reserve(28 * lattice.cells.size());
  for (const auto& cell : lattice.cells)
    for (int a = 0; a < 8; ++a)
      for (int b = a + 1; b < 8; ++b)
        pairs.emplace_back(std::min(cell[a], cell[b]), std::max(cell[a], cell[b]));
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  SpringNetwork network;
  for (const auto& [a, b] : pairs) {
    const double l0 = length(lattice.nodePositions[b] - lattice.nodePositions[a]);
    const double k = config.law == StiffnessLaw::PerRestLength ? config.stiffness / l0 : config.stiffness;
    addSpring(network, a, b, l0, k, config.damping);
  }
  if (auto ok = finalizeSpringNetwork(network, lattice.nodeCount()); !ok) return ok.error();
  return network;
}

/// Masses per node: cell volume / 8 per corner of each kept cell (Lumped) or uniform.
Result<std::vector<double>> latticeMasses(const EmbeddedLattice& lattice, const VolumeMassConfig& config) {
  const double total = config.total > 0.0 ? config.total : config.density * lattice.filledVolume;
  if (!(total > 0.0) || !std::isfinite(total))
    return Error{"lattice: neither a positive total mass (g) nor a positive density (g/mm^3) was given"};
  const double nodes = static_cast<double>(lattice.nodeCount());
  std::vector<double> masses(lattice.nodeCount(), total / nodes);
  if (config.distribution == MassDistribution::Lumped) {
    std::fill(masses.begin(), masses.end(), 0.0);
    const double perCorner = total / (8.0 * static_cast<double>(lattice.cells.size()));
    for (const auto& cell : lattice.cells)
      for (std::uint32_t n : cell)
        masses[n] += perCorner;
  }
  return masses;
}

/// Numbers the corners of the kept cells (grid order) into lattice.nodePositions and
/// lattice.cells; returns each grid cell's index into lattice.cells (-1 when not kept).
std::vector<std::int64_t> numberNodes(const detail::Grid& g, const std::vector<char>& keep,
                                      EmbeddedLattice& lattice) {
  const std::size_t nx = static_cast<std::size_t>(g.cells[0]) + 1,
                    ny = static_cast<std::size_t>(g.cells[1]) + 1;
  std::vector<std::int64_t> nodeOf(nx * ny * (static_cast<std::size_t>(g.cells[2]) + 1), -1);
  std::vector<std::int64_t> cellSlot(g.cellCount(), -1);
  for (int k = 0; k < g.cells[2]; ++k)
    for (int j = 0; j < g.cells[1]; ++j)
      for (int i = 0; i < g.cells[0]; ++i) {
        if (!keep[g.cellIndex(i, j, k)]) continue;
        std::array<std::uint32_t, 8> cell{};
        for (int c = 0; c < 8; ++c) {
          const std::size_t ci = static_cast<std::size_t>(i + (c & 1)),
                            cj = static_cast<std::size_t>(j + ((c >> 1) & 1)),
                            ck = static_cast<std::size_t>(k + ((c >> 2) & 1));
          std::int64_t& id = nodeOf[ci + nx * (cj + ny * ck)];
          if (id < 0) {
            id = static_cast<std::int64_t>(lattice.nodePositions.size());
            lattice.nodePositions.push_back(g.origin + Vec3d{ci * g.h, cj * g.h, ck * g.h});
          }
          cell[c] = static_cast<std::uint32_t>(id);
        }
        cellSlot[g.cellIndex(i, j, k)] = static_cast<std::int64_t>(lattice.cells.size());
        lattice.cells.push_back(cell);
      }
  return cellSlot;
}

}  // namespace

Result<EmbeddedLattice> buildEmbeddedLattice(std::span<const Float3> surfacePositions,
                                             std::span<const Triangle> triangles,
                                             const LatticeConfig& config) {
  if (auto closed = checkClosedSurface(surfacePositions.size(), triangles); !closed) return closed.error();
  auto grid = makeGrid(surfacePositions, config);
  if (!grid) return grid.error();
  const detail::Grid& g = *grid;

  // Keep the cells whose centre is inside, plus each cell that holds a surface vertex.
  std::vector<char> keep = detail::classifyCellCentres(g, surfacePositions, triangles);
  EmbeddedLattice lattice;
  lattice.insideCells = static_cast<std::size_t>(std::count(keep.begin(), keep.end(), 1));
  std::vector<std::size_t> vertexCell(surfacePositions.size());
  std::vector<Vec3d> local(surfacePositions.size());
  for (std::size_t s = 0; s < surfacePositions.size(); ++s) {
    const auto c = cellOf(g, surfacePositions[s], local[s]);
    vertexCell[s] = g.cellIndex(c[0], c[1], c[2]);
    if (!keep[vertexCell[s]]) {
      keep[vertexCell[s]] = 2;
      ++lattice.vertexCells;
    }
  }

  // Nodes: the corners of kept cells, numbered in grid order.
  const std::vector<std::int64_t> cellSlot = numberNodes(g, keep, lattice);
  lattice.origin = g.origin;
  lattice.cellSize = g.h;
  lattice.gridCells = g.cells;
  lattice.filledVolume = static_cast<double>(lattice.cells.size()) * g.h * g.h * g.h;

  // Each surface vertex: its cell's corners and trilinear weights.
  lattice.vertexNodes.resize(surfacePositions.size());
  lattice.vertexWeights.resize(surfacePositions.size());
  for (std::size_t s = 0; s < surfacePositions.size(); ++s) {
    lattice.vertexNodes[s] = lattice.cells[static_cast<std::size_t>(cellSlot[vertexCell[s]])];
    for (int c = 0; c < 8; ++c)
      lattice.vertexWeights[s][c] = trilinear(c, local[s]);
  }

  auto springs = latticeSprings(lattice, config.springs);
  if (!springs) return springs.error();
  lattice.springs = std::move(*springs);
  auto masses = latticeMasses(lattice, config.mass);
  if (!masses) return masses.error();
  lattice.masses = std::move(*masses);
  return lattice;
}

}  // namespace tissue::sim
