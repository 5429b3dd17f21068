// A small BVH for the CPU reference's ray-mesh queries (why hand-written: docs/DECISIONS.md).
#include "tissue/subsurface/triangle_bvh.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tissue::subsurface {
namespace {

using D3 = std::array<double, 3>;
constexpr std::uint32_t kLeafSize = 4;

D3 sub(const D3& a, const D3& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
D3 cross(const D3& a, const D3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double dot(const D3& a, const D3& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

// Slab test: does the ray cross the box within (tMin, tMax)?
bool hitsBox(const float lo[3], const float hi[3], const D3& o, const D3& inv, double tMin, double tMax) {
  for (int a = 0; a < 3; ++a) {
    double t0 = (double(lo[a]) - o[a]) * inv[a], t1 = (double(hi[a]) - o[a]) * inv[a];
    if (t0 > t1) std::swap(t0, t1);
    tMin = std::max(tMin, t0);
    tMax = std::min(tMax, t1);
    if (tMin > tMax) return false;
  }
  return true;
}

}  // namespace

TriangleBvh::TriangleBvh(std::span<const Float3> positions, std::span<const Triangle> triangles)
    : m_triangles(triangles.begin(), triangles.end()) {
  m_positions.reserve(positions.size());
  for (const Float3& p : positions)
    m_positions.push_back({p.x, p.y, p.z});
  m_order.resize(m_triangles.size());
  for (std::uint32_t i = 0; i < m_order.size(); ++i)
    m_order[i] = i;
  m_nodes.reserve(2 * m_triangles.size() / kLeafSize + 2);
  if (!m_triangles.empty()) build(0, std::uint32_t(m_triangles.size()));
}

std::uint32_t TriangleBvh::build(std::uint32_t first, std::uint32_t count) {
  const std::uint32_t index = std::uint32_t(m_nodes.size());
  m_nodes.emplace_back();
  Node node;
  for (int a = 0; a < 3; ++a)
    node.lo[a] = std::numeric_limits<float>::max(), node.hi[a] = -node.lo[a];
  float cLo[3] = {node.lo[0], node.lo[1], node.lo[2]}, cHi[3] = {node.hi[0], node.hi[1], node.hi[2]};
  auto centroid = [&](std::uint32_t t, int a) {
    const Triangle& tri = m_triangles[t];
    return (m_positions[tri[0]][a] + m_positions[tri[1]][a] + m_positions[tri[2]][a]) / 3.0;
  };
  for (std::uint32_t i = first; i < first + count; ++i) {
    for (std::uint32_t v : m_triangles[m_order[i]])
      for (int a = 0; a < 3; ++a) {
        // Round outwards so the float box contains the double triangle.
        node.lo[a] = std::min(node.lo[a], std::nextafter(float(m_positions[v][a]), -1e30f));
        node.hi[a] = std::max(node.hi[a], std::nextafter(float(m_positions[v][a]), 1e30f));
      }
    for (int a = 0; a < 3; ++a) {
      cLo[a] = std::min(cLo[a], float(centroid(m_order[i], a)));
      cHi[a] = std::max(cHi[a], float(centroid(m_order[i], a)));
    }
  }
  if (count <= kLeafSize) {
    node.first = first;
    node.count = count;
    m_nodes[index] = node;
    return index;
  }
  // Median split along the longest centroid extent.
  int axis = 0;
  for (int a = 1; a < 3; ++a)
    if (cHi[a] - cLo[a] > cHi[axis] - cLo[axis]) axis = a;
  const std::uint32_t half = count / 2;
  std::nth_element(m_order.begin() + first, m_order.begin() + first + half, m_order.begin() + first + count,
                   [&](std::uint32_t a, std::uint32_t b) { return centroid(a, axis) < centroid(b, axis); });
  build(first, half);  // left child is index + 1
  node.first = build(first + half, count - half);
  node.count = 0;
  m_nodes[index] = node;
  return index;
}

std::optional<RayHit> TriangleBvh::intersect(const D3& origin, const D3& dir, double tMin,
                                             double tMax) const {
  if (m_nodes.empty()) return std::nullopt;
  const D3 inv = {1.0 / dir[0], 1.0 / dir[1], 1.0 / dir[2]};
  std::optional<RayHit> best;
  std::uint32_t stack[64];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& node = m_nodes[stack[--top]];
    if (!hitsBox(node.lo, node.hi, origin, inv, tMin, tMax)) continue;
    if (node.count == 0) {
      const std::uint32_t self = std::uint32_t(&node - m_nodes.data());
      stack[top++] = node.first;
      stack[top++] = self + 1;
      continue;
    }
    for (std::uint32_t i = node.first; i < node.first + node.count; ++i) {
      // Möller-Trumbore.
      const Triangle& tri = m_triangles[m_order[i]];
      const D3 e1 = sub(m_positions[tri[1]], m_positions[tri[0]]);
      const D3 e2 = sub(m_positions[tri[2]], m_positions[tri[0]]);
      const D3 p = cross(dir, e2);
      const double det = dot(e1, p);
      if (std::abs(det) < 1e-14) continue;
      const D3 s = sub(origin, m_positions[tri[0]]);
      const double b1 = dot(s, p) / det;
      if (b1 < 0.0 || b1 > 1.0) continue;
      const D3 q = cross(s, e1);
      const double b2 = dot(dir, q) / det;
      if (b2 < 0.0 || b1 + b2 > 1.0) continue;
      const double t = dot(e2, q) / det;
      if (t <= tMin || t >= tMax) continue;
      tMax = t;
      best = RayHit{t, m_order[i], b1, b2};
    }
  }
  return best;
}

std::array<double, 3> TriangleBvh::faceNormal(std::uint32_t t) const {
  const Triangle& tri = m_triangles[t];
  const D3 n =
      cross(sub(m_positions[tri[1]], m_positions[tri[0]]), sub(m_positions[tri[2]], m_positions[tri[0]]));
  const double len = std::sqrt(dot(n, n));
  return len > 0.0 ? D3{n[0] / len, n[1] / len, n[2] / len} : D3{0.0, 0.0, 1.0};
}

}  // namespace tissue::subsurface
