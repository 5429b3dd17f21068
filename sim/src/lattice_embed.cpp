// The per-frame side of the embedded lattice: nodes to surface, surface forces to nodes, pins.
#include <algorithm>

#include "tissue/sim/lattice.h"

namespace tissue::sim {

void embedPositions(const EmbeddedLattice& lattice, std::span<const Vec3d> nodePositions,
                    std::span<Float3> surfaceOut) {
  const std::size_t n = std::min(surfaceOut.size(), lattice.vertexNodes.size());
  for (std::size_t s = 0; s < n; ++s) {
    Vec3d p{};
    for (int c = 0; c < 8; ++c)
      p += lattice.vertexWeights[s][c] * nodePositions[lattice.vertexNodes[s][c]];
    surfaceOut[s] = {static_cast<float>(p.x), static_cast<float>(p.y), static_cast<float>(p.z)};
  }
}

void scatterToNodes(const EmbeddedLattice& lattice, std::span<const Vec3d> surfaceForces,
                    std::span<Vec3d> nodeForcesOut) {
  std::fill(nodeForcesOut.begin(), nodeForcesOut.end(), Vec3d{});
  const std::size_t n = std::min(surfaceForces.size(), lattice.vertexNodes.size());
  for (std::size_t s = 0; s < n; ++s)
    for (int c = 0; c < 8; ++c)
      nodeForcesOut[lattice.vertexNodes[s][c]] += lattice.vertexWeights[s][c] * surfaceForces[s];
}

std::vector<std::uint32_t> nearestNodes(const EmbeddedLattice& lattice,
                                        std::span<const std::uint32_t> surfaceVertices) {
  std::vector<std::uint32_t> nodes;
  for (std::uint32_t s : surfaceVertices) {
    if (s >= lattice.vertexNodes.size()) continue;
    const auto& w = lattice.vertexWeights[s];
    const auto best = std::max_element(w.begin(), w.end()) - w.begin();
    nodes.push_back(lattice.vertexNodes[s][static_cast<std::size_t>(best)]);
  }
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  return nodes;
}

std::vector<std::uint32_t> cellNodes(const EmbeddedLattice& lattice,
                                     std::span<const std::uint32_t> surfaceVertices) {
  std::vector<std::uint32_t> nodes;
  for (std::uint32_t s : surfaceVertices)
    if (s < lattice.vertexNodes.size())
      nodes.insert(nodes.end(), lattice.vertexNodes[s].begin(), lattice.vertexNodes[s].end());
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  return nodes;
}

}  // namespace tissue::sim
