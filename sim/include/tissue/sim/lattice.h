#pragma once
/// \file
/// An embedded lattice: a closed surface filled with a coarse regular lattice of hexahedral
/// cells whose corners are the simulated nodes; every surface (render) vertex rides inside its
/// cell with trilinear weights. The organ keeps its volume under a poke (the lattice's springs
/// fill it) while the simulation stays small (a few hundred to a few thousand nodes whatever the
/// render mesh's size). The surface may be of any size; only the lattice is simulated.
///
/// Pass the surface's geometric vertices (one per point of the surface): a mesh split at UV
/// seams has boundary edges along the seams and is rejected as open.

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "tissue/core/result.h"
#include "tissue/core/types.h"
#include "tissue/sim/mass.h"
#include "tissue/sim/spring_network.h"
#include "tissue/sim/vec3.h"

namespace tissue::sim {

/// How to build the lattice.
struct LatticeConfig {
  double cellSize = 0.0;           ///< mm, the cells' edge; 0 to use cellsAlongLongestAxis
  int cellsAlongLongestAxis = 12;  ///< cells across the surface's longest bounding-box side
  /// Every lattice spring (cell edges, face and body diagonals) uses springs.stiffness under
  /// springs.law (Constant: N/mm; PerRestLength: N, k_i = k / L0_i) and springs.damping (N*s/mm);
  /// springs.bendingStiffness is unused.
  SpringConfig springs{};
  /// Lumped: each kept cell gives volume / 8 to each corner; Uniform: every node the same. The
  /// total is mass.total (g), or mass.density (g/mm^3) times the filled volume (mm^3).
  VolumeMassConfig mass{};
};

/// The lattice, its springs and masses, and the embedding of the surface vertices.
struct EmbeddedLattice {
  std::vector<Vec3d> nodePositions;                       ///< rest positions, mm, #nodes
  std::vector<std::array<std::uint32_t, 8>> cells;        ///< corner nodes of each kept cell, bit 0 = +x,
                                                          ///< bit 1 = +y, bit 2 = +z
  SpringNetwork springs;                                  ///< over the nodes
  std::vector<double> masses;                             ///< g, #nodes
  std::vector<std::array<std::uint32_t, 8>> vertexNodes;  ///< the 8 corner nodes of each surface
                                                          ///< vertex's cell, #surface vertices
  std::vector<std::array<double, 8>> vertexWeights;       ///< trilinear weights (sum 1), #surface vertices
  Vec3d origin;                                           ///< mm, the grid's minimum corner
  double cellSize = 0.0;                                  ///< mm
  std::array<int, 3> gridCells{};                         ///< cells of the full grid along x, y, z
  std::size_t insideCells = 0;  ///< cells kept because their centre is inside the surface
  std::size_t vertexCells = 0;  ///< cells kept only because they contain a surface vertex
  double filledVolume = 0.0;    ///< mm^3, kept cells times cellSize^3

  std::size_t nodeCount() const { return nodePositions.size(); }
};

/// Fails, naming the first offending edge (1-based vertices), when `triangles` over
/// `vertexCount` vertices are not a closed 2-manifold: an edge with one triangle (open surface),
/// an edge with more than two (non-manifold), an index out of range or a repeated vertex.
Result<void> checkClosedSurface(std::size_t vertexCount, std::span<const Triangle> triangles);

/// Fills the closed surface (`surfacePositions` in mm, `triangles`) with a regular lattice:
/// the cells whose centre is inside (ray parity along +x, the ray jittered off grid lines) plus
/// every cell that contains a surface vertex, so every vertex is embedded. Springs join all 28
/// pairs of each cell's corners (12 edges, 12 face and 4 body diagonals; without diagonals a hex
/// lattice has no shear stiffness), each pair once. Fails on an open or non-manifold surface,
/// bad settings, or a lattice of more than 4 million grid cells.
Result<EmbeddedLattice> buildEmbeddedLattice(std::span<const Float3> surfacePositions,
                                             std::span<const Triangle> triangles,
                                             const LatticeConfig& config);

/// Maps node positions (mm, #nodes) to the surface vertices (mm, #surface vertices) by the
/// trilinear weights: surfaceOut[s] = sum_c w_sc x[node_sc]. Exact for any affine map of the
/// nodes. Writes min(surfaceOut.size(), #surface vertices) vertices.
void embedPositions(const EmbeddedLattice& lattice, std::span<const Vec3d> nodePositions,
                    std::span<Float3> surfaceOut);

/// Distributes forces applied at surface vertices (g*mm/s^2, #surface vertices) to the nodes
/// (the transpose of the weights): nodeForcesOut (#nodes) is set to sum_s w_sc f_s. The total
/// force and its moment about any point (to first order) are kept.
void scatterToNodes(const EmbeddedLattice& lattice, std::span<const Vec3d> surfaceForces,
                    std::span<Vec3d> nodeForcesOut);

/// For each of `surfaceVertices`, the corner node of its cell with the largest weight (the
/// nearest node); sorted, each once.
std::vector<std::uint32_t> nearestNodes(const EmbeddedLattice& lattice,
                                        std::span<const std::uint32_t> surfaceVertices);

/// All 8 corner nodes of the cells of `surfaceVertices`, sorted, each once: pin these to hold
/// the vertices exactly still.
std::vector<std::uint32_t> cellNodes(const EmbeddedLattice& lattice,
                                     std::span<const std::uint32_t> surfaceVertices);

}  // namespace tissue::sim
