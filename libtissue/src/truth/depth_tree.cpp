// Nearest surface point queries for the layer depth (depth_tree.h).
#include "depth_tree.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tissue::truth::detail {
namespace {

constexpr std::uint32_t kLeafSize = 4;

double boxDistance2(const glm::dvec3& p, const glm::dvec3& lo, const glm::dvec3& hi) {
  const glm::dvec3 d = glm::max(glm::max(lo - p, p - hi), glm::dvec3(0.0));
  return glm::dot(d, d);
}

}  // namespace

// The Voronoi region of p among the triangle's vertices, edges and face (Ericson 2005, §5.1.5).
glm::dvec2 closestOnTriangle(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b,
                             const glm::dvec3& c) {
  const glm::dvec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
  if (d1 <= 0.0 && d2 <= 0.0) return {0.0, 0.0};
  const glm::dvec3 bp = p - b;
  const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
  if (d3 >= 0.0 && d4 <= d3) return {1.0, 0.0};
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return {d1 / (d1 - d3), 0.0};
  const glm::dvec3 cp = p - c;
  const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
  if (d6 >= 0.0 && d5 <= d6) return {0.0, 1.0};
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return {0.0, d2 / (d2 - d6)};
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return {1.0 - w, w};
  }
  const double denom = 1.0 / (va + vb + vc);
  return {vb * denom, vc * denom};
}

DepthTree::DepthTree(std::span<const Float3> positions, std::span<const Triangle> triangles)
    : m_triangles(triangles.begin(), triangles.end()) {
  for (const Float3& p : positions)
    m_positions.emplace_back(p.x, p.y, p.z);
  m_order.resize(m_triangles.size());
  for (std::uint32_t i = 0; i < m_order.size(); ++i)
    m_order[i] = i;
  if (!m_triangles.empty()) build(0, std::uint32_t(m_triangles.size()));
}

std::uint32_t DepthTree::build(std::uint32_t first, std::uint32_t count) {
  const auto index = std::uint32_t(m_nodes.size());
  m_nodes.emplace_back();
  Node node{glm::dvec3(std::numeric_limits<double>::max()), glm::dvec3(-std::numeric_limits<double>::max())};
  glm::dvec3 cLo = node.lo, cHi = node.hi;
  auto centroid = [&](std::uint32_t t) {
    const Triangle& tri = m_triangles[t];
    return (m_positions[tri[0]] + m_positions[tri[1]] + m_positions[tri[2]]) / 3.0;
  };
  for (std::uint32_t i = first; i < first + count; ++i) {
    for (std::uint32_t v : m_triangles[m_order[i]]) {
      node.lo = glm::min(node.lo, m_positions[v]);
      node.hi = glm::max(node.hi, m_positions[v]);
    }
    cLo = glm::min(cLo, centroid(m_order[i]));
    cHi = glm::max(cHi, centroid(m_order[i]));
  }
  if (count <= kLeafSize) {
    node.first = first;
    node.count = count;
    m_nodes[index] = node;
    return index;
  }
  const glm::dvec3 extent = cHi - cLo;
  const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
  const std::uint32_t half = count / 2;
  std::nth_element(m_order.begin() + first, m_order.begin() + first + half, m_order.begin() + first + count,
                   [&](std::uint32_t a, std::uint32_t b) { return centroid(a)[axis] < centroid(b)[axis]; });
  build(first, half);
  node.first = build(first + half, count - half);
  node.count = 0;
  m_nodes[index] = node;
  return index;
}

std::optional<SurfacePoint> DepthTree::nearest(const glm::dvec3& p, double maxDistanceMm) const {
  SurfacePoint best;
  double best2 = maxDistanceMm * maxDistanceMm;
  bool found = false;
  if (m_nodes.empty()) return std::nullopt;
  std::uint32_t stack[64];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const std::uint32_t ni = stack[--top];
    const Node& node = m_nodes[ni];
    if (boxDistance2(p, node.lo, node.hi) >= best2) continue;
    if (node.count == 0) {
      // Visit the nearer child first: push it last.
      const std::uint32_t left = ni + 1, right = node.first;
      const double dl = boxDistance2(p, m_nodes[left].lo, m_nodes[left].hi);
      const double dr = boxDistance2(p, m_nodes[right].lo, m_nodes[right].hi);
      stack[top++] = dl < dr ? right : left;
      stack[top++] = dl < dr ? left : right;
      continue;
    }
    for (std::uint32_t i = node.first; i < node.first + node.count; ++i) {
      const Triangle& tri = m_triangles[m_order[i]];
      const glm::dvec3 &a = m_positions[tri[0]], &b = m_positions[tri[1]], &c = m_positions[tri[2]];
      const glm::dvec2 w = closestOnTriangle(p, a, b, c);
      const glm::dvec3 q = a + w.x * (b - a) + w.y * (c - a);
      const double d2 = glm::dot(q - p, q - p);
      if (d2 < best2) {
        best2 = d2;
        best = {0.0, m_order[i], w.x, w.y};
        found = true;
      }
    }
  }
  if (!found) return std::nullopt;
  best.distanceMm = std::sqrt(best2);
  return best;
}

}  // namespace tissue::truth::detail
