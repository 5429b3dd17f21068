#include "tissue/sim/tet_springs.h"

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "tissue/sim/vec3.h"

namespace tissue::sim {

Result<SpringNetwork> buildTetEdgeSprings(std::span<const Float3> positions, std::span<const Tet> tets,
                                          const SpringConfig& config, TetSpringReport* report) {
  // The six edges of every tet as (lo, hi) pairs; sorting and removing repeats leaves one per
  // unique edge, in a fixed order (deterministic networks).
  std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
  edges.reserve(6 * tets.size());
  for (std::size_t t = 0; t < tets.size(); ++t) {
    for (std::uint32_t v : tets[t])
      if (v >= positions.size())
        return Error{"tet " + std::to_string(t + 1) + " (1-based) refers to vertex " + std::to_string(v + 1) +
                     " of " + std::to_string(positions.size()) + "; fix the index arrays"};
    for (std::size_t a = 0; a < 4; ++a)
      for (std::size_t b = a + 1; b < 4; ++b)
        edges.emplace_back(std::min(tets[t][a], tets[t][b]), std::max(tets[t][a], tets[t][b]));
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());

  SpringNetwork network;
  for (const auto& [a, b] : edges) {
    const Float3 &p = positions[a], &q = positions[b];
    const double l0 = length(Vec3d{q.x, q.y, q.z} - Vec3d{p.x, p.y, p.z});
    const double k = config.law == StiffnessLaw::PerRestLength ? config.stiffness / l0 : config.stiffness;
    addSpring(network, a, b, l0, k, config.damping);
  }
  if (auto ok = finalizeSpringNetwork(network, positions.size()); !ok) return ok.error();
  if (report) *report = {tets.size(), network.size()};
  return network;
}

}  // namespace tissue::sim
