// The inspection fields from plain arrays (no VTK): built with and without it.
#include "tissue/inspect/organ_fields.h"

#include <algorithm>
#include <cmath>

#include "tissue/core/vec_math.h"

namespace tissue::inspect {

std::vector<float> springStrain(std::span<const Float3> positions, std::span<const Edge> edges,
                                std::span<const double> restLengths) {
  std::vector<float> strain(edges.size(), 0.0f);
  for (std::size_t s = 0; s < edges.size() && s < restLengths.size(); ++s) {
    const Float3 a = positions[edges[s][0]], b = positions[edges[s][1]];
    const double dx = double(b.x) - double(a.x), dy = double(b.y) - double(a.y),
                 dz = double(b.z) - double(a.z);
    const double length = std::sqrt(dx * dx + dy * dy + dz * dz);
    strain[s] = float(length / restLengths[s] - 1.0);
  }
  return strain;
}

std::vector<float> vertexStretch(std::size_t vertexCount, std::span<const Edge> edges,
                                 std::span<const float> strain) {
  std::vector<double> sum(vertexCount, 0.0);
  std::vector<int> count(vertexCount, 0);
  for (std::size_t s = 0; s < edges.size() && s < strain.size(); ++s)
    for (std::uint32_t v : edges[s]) {
      sum[v] += 1.0 + double(strain[s]);
      ++count[v];
    }
  std::vector<float> stretch(vertexCount, 1.0f);
  for (std::size_t v = 0; v < vertexCount; ++v)
    if (count[v] > 0) stretch[v] = float(sum[v] / count[v]);
  return stretch;
}

std::vector<float> planeResidualMm(std::span<const Float3> positions, std::span<const Float3> normals,
                                   std::span<const Float4> planes, std::span<const std::uint32_t> offsets,
                                   std::span<const std::uint32_t> neighbours) {
  std::vector<float> residual(positions.size(), 0.0f);
  for (std::size_t v = 0; v + 1 < offsets.size() && v < positions.size(); ++v) {
    // The plane's point P_V = V + d N_V (eq. 14) and normal N_S.
    const Float4& plane = planes[v];
    const Float3 n{plane.x, plane.y, plane.z};
    const Float3 p = positions[v] + plane.w * normals[v];
    double sum = 0.0;
    const std::uint32_t first = offsets[v], last = offsets[v + 1];
    for (std::uint32_t k = first; k < last; ++k) {
      const double distance = double(dot(n, positions[neighbours[k]] - p));
      sum += distance * distance;
    }
    if (last > first) residual[v] = float(std::sqrt(sum / double(last - first)));
  }
  return residual;
}

std::vector<float> handednessFlips(std::span<const Float4> tangents,
                                   std::span<const std::uint32_t> geometricIndex) {
  // Per geometric vertex: which handedness its copies have (bit 0: w > 0, bit 1: w < 0).
  std::uint32_t geometricCount = 0;
  for (std::uint32_t g : geometricIndex)
    geometricCount = std::max(geometricCount, g + 1);
  std::vector<std::uint8_t> seen(geometricCount, 0);
  for (std::size_t r = 0; r < tangents.size() && r < geometricIndex.size(); ++r)
    seen[geometricIndex[r]] |= tangents[r].w < 0.0f ? 2 : 1;
  std::vector<float> flips(tangents.size(), 0.0f);
  for (std::size_t r = 0; r < tangents.size() && r < geometricIndex.size(); ++r)
    flips[r] = seen[geometricIndex[r]] == 3 ? 1.0f : 0.0f;
  return flips;
}

std::vector<float> relativeTextureStretch(std::span<const Float2> stretchMmPerUv, float uvPerMm) {
  std::vector<float> out(stretchMmPerUv.size(), 0.0f);
  for (std::size_t t = 0; t < out.size(); ++t)
    out[t] = std::sqrt(stretchMmPerUv[t].x * stretchMmPerUv[t].y) * uvPerMm;
  return out;
}

std::vector<float> triangleMeans(std::span<const float> perVertex, std::span<const Triangle> triangles) {
  std::vector<float> out(triangles.size(), 0.0f);
  for (std::size_t t = 0; t < triangles.size(); ++t)
    out[t] = (perVertex[triangles[t][0]] + perVertex[triangles[t][1]] + perVertex[triangles[t][2]]) / 3.0f;
  return out;
}

}  // namespace tissue::inspect
