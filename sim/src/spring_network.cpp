#include "tissue/sim/spring_network.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "tissue/sim/units.h"
#include "tissue/sim/vec3.h"

namespace tissue::sim {
namespace {

Vec3d toVec(const Float3& p) {
  return {p.x, p.y, p.z};
}

/// An undirected edge (lo < hi) and the vertex opposite to it in one triangle.
struct HalfEdge {
  std::uint32_t lo, hi, opposite;
  bool operator<(const HalfEdge& o) const { return std::pair(lo, hi) < std::pair(o.lo, o.hi); }
};

/// Stiffness of one spring in N/mm under `law`.
double lawStiffness(const SpringConfig& config, double value, double restLength) {
  return config.law == StiffnessLaw::PerRestLength ? value / restLength : value;
}

}  // namespace

void addSpring(SpringNetwork& network, std::uint32_t i, std::uint32_t j, double restLengthMm,
               double stiffnessNPerMm, double dampingNsPerMm) {
  network.i.push_back(i);
  network.j.push_back(j);
  network.restLength.push_back(restLengthMm);
  network.stiffness.push_back(stiffnessFromNewtonPerMm(stiffnessNPerMm));
  network.damping.push_back(dampingFromNewtonSecondPerMm(dampingNsPerMm));
}

Result<void> finalizeSpringNetwork(SpringNetwork& network, std::size_t vertexCount) {
  const std::size_t n = network.size();
  for (std::size_t e = 0; e < n; ++e) {
    if (network.i[e] >= vertexCount || network.j[e] >= vertexCount || network.i[e] == network.j[e])
      return Error{"spring " + std::to_string(e) + " joins vertices " + std::to_string(network.i[e]) +
                   " and " + std::to_string(network.j[e]) + " of " + std::to_string(vertexCount) +
                   "; give two different vertices in range"};
    if (!(network.restLength[e] > 0.0) || !std::isfinite(network.restLength[e]))
      return Error{"spring " + std::to_string(e) + " has rest length " +
                   std::to_string(network.restLength[e]) +
                   " mm; rest lengths must be positive (coincident vertices?)"};
  }
  // Counting sort by vertex: spring indices come out ascending per vertex.
  network.vertexSpringOffsets.assign(vertexCount + 1, 0);
  for (std::size_t e = 0; e < n; ++e) {
    ++network.vertexSpringOffsets[network.i[e] + 1];
    ++network.vertexSpringOffsets[network.j[e] + 1];
  }
  for (std::size_t k = 0; k < vertexCount; ++k)
    network.vertexSpringOffsets[k + 1] += network.vertexSpringOffsets[k];
  network.vertexSprings.assign(2 * n, 0);
  std::vector<std::uint32_t> fill(network.vertexSpringOffsets.begin(), network.vertexSpringOffsets.end() - 1);
  for (std::size_t e = 0; e < n; ++e) {
    network.vertexSprings[fill[network.i[e]]++] = static_cast<std::uint32_t>(e);
    network.vertexSprings[fill[network.j[e]]++] = static_cast<std::uint32_t>(e);
  }
  return {};
}

Result<SpringNetwork> buildSurfaceSprings(std::span<const Float3> positions,
                                          std::span<const Triangle> triangles, const SpringConfig& config,
                                          SpringBuildReport* report) {
  // Collect the three edges of every triangle with their opposite vertices.
  std::vector<HalfEdge> halfEdges;
  halfEdges.reserve(3 * triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const Triangle& tri = triangles[t];
    for (int c = 0; c < 3; ++c) {
      if (tri[c] >= positions.size())
        return Error{"triangle " + std::to_string(t) + " refers to vertex " + std::to_string(tri[c]) +
                     " of " + std::to_string(positions.size()) + "; fix the index arrays"};
    }
    for (int c = 0; c < 3; ++c) {
      const std::uint32_t a = tri[c], b = tri[(c + 1) % 3], o = tri[(c + 2) % 3];
      halfEdges.push_back({std::min(a, b), std::max(a, b), o});
    }
  }
  std::stable_sort(halfEdges.begin(), halfEdges.end());

  // One edge spring per unique edge; a bending spring across each edge with two triangles.
  SpringNetwork network;
  SpringBuildReport counts;
  auto restLength = [&](std::uint32_t a, std::uint32_t b) {
    return length(toVec(positions[b]) - toVec(positions[a]));
  };
  for (std::size_t k = 0; k < halfEdges.size();) {
    std::size_t end = k;
    while (end < halfEdges.size() && halfEdges[end].lo == halfEdges[k].lo &&
           halfEdges[end].hi == halfEdges[k].hi)
      ++end;
    const HalfEdge& h = halfEdges[k];
    const double l0 = restLength(h.lo, h.hi);
    addSpring(network, h.lo, h.hi, l0, lawStiffness(config, config.stiffness, l0), config.damping);
    ++counts.edgeSprings;
    const std::size_t faces = end - k;
    if (faces == 1) ++counts.boundaryEdges;
    if (faces > 2) ++counts.nonManifoldEdges;
    if (faces == 2 && config.bendingStiffness > 0.0 && halfEdges[k].opposite != halfEdges[k + 1].opposite) {
      const std::uint32_t a = std::min(halfEdges[k].opposite, halfEdges[k + 1].opposite);
      const std::uint32_t b = std::max(halfEdges[k].opposite, halfEdges[k + 1].opposite);
      const double lb = restLength(a, b);
      addSpring(network, a, b, lb, lawStiffness(config, config.bendingStiffness, lb), config.damping);
      ++counts.bendingSprings;
    }
    k = end;
  }
  if (auto ok = finalizeSpringNetwork(network, positions.size()); !ok) return ok.error();
  if (report) *report = counts;
  return network;
}

}  // namespace tissue::sim
