// UV atlas, step 1: segmentation into disk-like charts by region growing in a normal cone.
#include <algorithm>
#include <cmath>
#include <deque>
#include <numbers>
#include <unordered_map>

#include "uv_atlas_steps.h"
#include "vec3.h"

namespace tissue::mesh::atlas {

using namespace detail;

std::vector<std::int32_t> triangleAdjacency(std::span<const Triangle> triangles, std::size_t vertexCount) {
  // Directed edge (a, b) -> triangle; a consistently oriented manifold has each once.
  std::unordered_map<std::uint64_t, std::int32_t> edges;
  edges.reserve(triangles.size() * 3);
  const auto key = [vertexCount](std::uint32_t a, std::uint32_t b) {
    return std::uint64_t(a) * std::uint64_t(vertexCount) + b;
  };
  for (std::size_t t = 0; t < triangles.size(); ++t)
    for (int k = 0; k < 3; ++k)
      edges.emplace(key(triangles[t][k], triangles[t][(k + 1) % 3]), std::int32_t(t));
  std::vector<std::int32_t> adjacent(triangles.size() * 3, -1);
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    for (int k = 0; k < 3; ++k) {
      const auto it = edges.find(key(triangles[t][(k + 1) % 3], triangles[t][k]));
      if (it != edges.end() && it->second != std::int32_t(t)) adjacent[3 * t + k] = it->second;
    }
  }
  return adjacent;
}

std::vector<std::uint32_t> growCharts(std::span<const Float3> faceNormals,
                                      std::span<const std::int32_t> adjacency, float maxDeviationDeg) {
  constexpr std::uint32_t kNone = ~0u;
  const float cosMax = std::cos(maxDeviationDeg * std::numbers::pi_v<float> / 180.0f);
  std::vector<std::uint32_t> chart(faceNormals.size(), kNone);
  std::uint32_t next = 0;
  std::deque<std::uint32_t> queue;
  for (std::uint32_t seed = 0; seed < faceNormals.size(); ++seed) {
    if (chart[seed] != kNone) continue;
    // Breadth-first growth from the seed; the cone axis is the seed's normal, so every member
    // is within maxDeviationDeg of it and the chart projects without folds onto its plane.
    const Float3 axis = faceNormals[seed];
    chart[seed] = next;
    queue.assign(1, seed);
    while (!queue.empty()) {
      const std::uint32_t t = queue.front();
      queue.pop_front();
      for (int k = 0; k < 3; ++k) {
        const std::int32_t n = adjacency[3 * t + k];
        if (n < 0 || chart[std::size_t(n)] != kNone) continue;
        if (dot(faceNormals[std::size_t(n)], axis) < cosMax) continue;
        chart[std::size_t(n)] = next;
        queue.push_back(std::uint32_t(n));
      }
    }
    ++next;
  }
  return chart;
}

std::vector<std::vector<std::uint32_t>> connectedParts(std::span<const std::uint32_t> chartTriangles,
                                                       std::span<const std::int32_t> adjacency,
                                                       std::size_t triangleCount) {
  // -2: not in the set, -1: in the set and unvisited, >= 0: part index.
  std::vector<std::int32_t> part(triangleCount, -2);
  for (std::uint32_t t : chartTriangles)
    part[t] = -1;
  std::vector<std::vector<std::uint32_t>> parts;
  std::vector<std::uint32_t> stack;
  for (std::uint32_t seed : chartTriangles) {
    if (part[seed] != -1) continue;
    const auto index = std::int32_t(parts.size());
    parts.emplace_back();
    part[seed] = index;
    stack.assign(1, seed);
    while (!stack.empty()) {
      const std::uint32_t t = stack.back();
      stack.pop_back();
      parts.back().push_back(t);
      for (int k = 0; k < 3; ++k) {
        const std::int32_t n = adjacency[3 * t + k];
        if (n >= 0 && part[std::size_t(n)] == -1) {
          part[std::size_t(n)] = index;
          stack.push_back(std::uint32_t(n));
        }
      }
    }
  }
  return parts;
}

bool isDiskLike(std::span<const Triangle> triangles, std::span<const std::uint32_t> chartTriangles,
                std::span<const std::int32_t> adjacency) {
  if (connectedParts(chartTriangles, adjacency, triangles.size()).size() != 1) return false;
  std::vector<bool> inChart(triangles.size(), false);
  for (std::uint32_t t : chartTriangles)
    inChart[t] = true;
  // Border edges per vertex; the vertex set.
  std::unordered_map<std::uint32_t, int> borderEdges;
  std::size_t border = 0;
  for (std::uint32_t t : chartTriangles) {
    for (int k = 0; k < 3; ++k) {
      borderEdges.try_emplace(triangles[t][k], 0);
      const std::int32_t n = adjacency[3 * t + k];
      if (n >= 0 && inChart[std::size_t(n)]) continue;
      ++border;
      ++borderEdges[triangles[t][k]];
      ++borderEdges[triangles[t][(k + 1) % 3]];
    }
  }
  for (const auto& [vertex, count] : borderEdges)
    if (count != 0 && count != 2) return false;  // a pinched vertex: two border loops touch
  // Euler characteristic V - E + F = 2 - 2g - b is 1 only for a disk (g = 0, b = 1).
  const auto f = std::int64_t(chartTriangles.size());
  const std::int64_t e = (3 * f + std::int64_t(border)) / 2;
  return std::int64_t(borderEdges.size()) - e + f == 1 && border > 0;
}

std::vector<std::vector<std::uint32_t>> splitChart(std::span<const Float3> positions,
                                                   std::span<const Triangle> triangles,
                                                   std::span<const std::uint32_t> chartTriangles,
                                                   std::span<const std::int32_t> adjacency) {
  // Centroids and the widest axis of their bounding box.
  std::vector<std::pair<float, std::uint32_t>> keyed;
  keyed.reserve(chartTriangles.size());
  Float3 lo{1e30f, 1e30f, 1e30f}, hi{-1e30f, -1e30f, -1e30f};
  std::vector<Float3> centroid(chartTriangles.size());
  for (std::size_t i = 0; i < chartTriangles.size(); ++i) {
    const Triangle& tri = triangles[chartTriangles[i]];
    centroid[i] = (positions[tri[0]] + positions[tri[1]] + positions[tri[2]]) * (1.0f / 3.0f);
    lo = {std::min(lo.x, centroid[i].x), std::min(lo.y, centroid[i].y), std::min(lo.z, centroid[i].z)};
    hi = {std::max(hi.x, centroid[i].x), std::max(hi.y, centroid[i].y), std::max(hi.z, centroid[i].z)};
  }
  const Float3 extent = hi - lo;
  const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
  for (std::size_t i = 0; i < chartTriangles.size(); ++i) {
    const float c = axis == 0 ? centroid[i].x : (axis == 1 ? centroid[i].y : centroid[i].z);
    keyed.emplace_back(c, chartTriangles[i]);
  }
  // Median split; each half's connected components become charts.
  const auto middle = keyed.begin() + std::ptrdiff_t(keyed.size() / 2);
  std::nth_element(keyed.begin(), middle, keyed.end());
  std::vector<std::uint32_t> halves[2];
  for (auto it = keyed.begin(); it != keyed.end(); ++it)
    halves[it < middle ? 0 : 1].push_back(it->second);
  std::vector<std::vector<std::uint32_t>> out;
  for (const auto& half : halves)
    for (auto& part : connectedParts(half, adjacency, triangles.size()))
      out.push_back(std::move(part));
  return out;
}

}  // namespace tissue::mesh::atlas
