#include "tissue/mesh/shading_topology.h"

#include <algorithm>
#include <cmath>

namespace tissue::mesh {

VertexCorners buildVertexCorners(std::span<const Triangle> triangles, std::size_t vertexCount,
                                 std::span<const std::uint8_t> keepTriangle) {
  // Counting sort of the corners by vertex; a stable fill keeps each list ascending.
  VertexCorners vc;
  vc.offsets.assign(vertexCount + 1, 0);
  const auto kept = [&](std::size_t t) { return keepTriangle.empty() || keepTriangle[t] != 0; };
  for (std::size_t t = 0; t < triangles.size(); ++t)
    if (kept(t))
      for (int k = 0; k < 3; ++k)
        ++vc.offsets[triangles[t][k] + 1];
  for (std::size_t v = 0; v < vertexCount; ++v)
    vc.offsets[v + 1] += vc.offsets[v];
  vc.corners.resize(vc.offsets[vertexCount]);
  std::vector<std::uint32_t> fill(vc.offsets.begin(), vc.offsets.end() - 1);
  for (std::size_t t = 0; t < triangles.size(); ++t)
    if (kept(t))
      for (std::uint32_t k = 0; k < 3; ++k)
        vc.corners[fill[triangles[t][k]]++] = std::uint32_t(3 * t) + k;
  return vc;
}

TangentTopology buildTangentTopology(std::span<const Float2> uvs, std::span<const Triangle> triangles,
                                     std::span<const std::uint32_t> geometricIndex) {
  TangentTopology topo;
  // Per-triangle UV constants; triangles without UV area carry no gradient and are left out.
  topo.uvBases.resize(triangles.size());
  std::vector<std::uint8_t> keep(triangles.size(), 0);
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const auto& tri = triangles[t];
    UvBasis& b = topo.uvBases[t];
    b.s1 = uvs[tri[1]].x - uvs[tri[0]].x, b.t1 = uvs[tri[1]].y - uvs[tri[0]].y;
    b.s2 = uvs[tri[2]].x - uvs[tri[0]].x, b.t2 = uvs[tri[2]].y - uvs[tri[0]].y;
    const float det = b.s1 * b.t2 - b.s2 * b.t1;
    b.hasUvArea = std::abs(det) >= 1e-20f;
    b.r = b.hasUvArea ? 1.0f / det : 0.0f;
    keep[t] = b.hasUvArea ? 1 : 0;
  }
  topo.corners = buildVertexCorners(triangles, uvs.size(), keep);
  // Seam groups: the render vertices of each geometric vertex, ascending (counting sort).
  const std::size_t n = uvs.size();
  topo.copies.resize(n);
  if (geometricIndex.empty()) {
    topo.copyOffsets.resize(n + 1);
    for (std::uint32_t i = 0; i <= n; ++i)
      topo.copyOffsets[i] = i;
    for (std::uint32_t i = 0; i < n; ++i)
      topo.copies[i] = i;
    return topo;
  }
  const std::size_t groups =
      n == 0 ? 0 : std::size_t(*std::max_element(geometricIndex.begin(), geometricIndex.end())) + 1;
  topo.copyOffsets.assign(groups + 1, 0);
  for (std::size_t i = 0; i < n; ++i)
    ++topo.copyOffsets[geometricIndex[i] + 1];
  for (std::size_t g = 0; g < groups; ++g)
    topo.copyOffsets[g + 1] += topo.copyOffsets[g];
  std::vector<std::uint32_t> fill(topo.copyOffsets.begin(), topo.copyOffsets.end() - 1);
  for (std::uint32_t i = 0; i < n; ++i)
    topo.copies[fill[geometricIndex[i]]++] = i;
  return topo;
}

}  // namespace tissue::mesh
