#pragma once
// Private: the depth of a point inside the mesh, its distance to the nearest surface point, with
// that point's triangle and barycentrics (for its texture coordinate), for the BVH back end of
// RayMesh. A median-split BVH over the triangles, traversed nearest box first (Ericson, Real-Time Collision
// Detection, 2005, §5.1.5 for the closest point on a triangle, §6 for the hierarchy).

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "tissue/core/types.h"
#include "tissue/truth/ray_mesh.h"

namespace tissue::truth::detail {

/// Closest point on triangle abc to p (Ericson 2005, §5.1.5): the barycentric weights of b and c.
glm::dvec2 closestOnTriangle(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b,
                             const glm::dvec3& c);

class DepthTree {
 public:
  DepthTree(std::span<const Float3> positions, std::span<const Triangle> triangles);
  /// The nearest surface point within `maxDistanceMm` of p, or none.
  std::optional<SurfacePoint> nearest(const glm::dvec3& p, double maxDistanceMm) const;

 private:
  struct Node {
    glm::dvec3 lo, hi;
    std::uint32_t first = 0;  // leaf: first index in m_order; inner: right child
    std::uint32_t count = 0;  // leaf: triangle count; inner: 0 (left child is the next node)
  };
  std::uint32_t build(std::uint32_t first, std::uint32_t count);

  std::vector<glm::dvec3> m_positions;
  std::vector<Triangle> m_triangles;
  std::vector<std::uint32_t> m_order;
  std::vector<Node> m_nodes;
};

}  // namespace tissue::truth::detail
