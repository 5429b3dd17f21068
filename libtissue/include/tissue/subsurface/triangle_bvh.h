#pragma once
/// \file
/// A small bounding-volume hierarchy over a triangle mesh for the CPU reference: the first
/// surface point a ray meets (the light's true entry point K, and camera rays). Built once per
/// deformed state (about 10 ms for 30k triangles); positions in mm. Why not Embree:
/// docs/DECISIONS.md.

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "tissue/core/types.h"

namespace tissue::subsurface {

/// Where a ray met a triangle.
struct RayHit {
  double t = 0.0;              ///< distance along the (unit) direction, mm
  std::uint32_t triangle = 0;  ///< index into the triangle array
  double b1 = 0.0;             ///< barycentric weight of the triangle's second vertex
  double b2 = 0.0;             ///< barycentric weight of the third vertex
};

/// Binary BVH with median splits along the longest axis; Möller-Trumbore triangle tests in
/// double precision. Immutable after construction.
class TriangleBvh {
 public:
  /// \param positions  #V vertex positions, mm (copied)
  /// \param triangles  #F triangles (copied)
  TriangleBvh(std::span<const Float3> positions, std::span<const Triangle> triangles);

  /// The nearest hit with t in (tMin, tMax) along origin + t dir (`dir` unit), or none.
  std::optional<RayHit> intersect(const std::array<double, 3>& origin, const std::array<double, 3>& dir,
                                  double tMin, double tMax) const;

  /// Unit geometric normal of triangle `t` (counter-clockwise seen from outside: outward).
  std::array<double, 3> faceNormal(std::uint32_t t) const;

 private:
  struct Node {
    float lo[3], hi[3];
    std::uint32_t first = 0;  // leaf: first triangle in m_order; inner: right child
    std::uint32_t count = 0;  // leaf: triangle count; inner: 0
  };
  std::uint32_t build(std::uint32_t first, std::uint32_t count);

  std::vector<std::array<double, 3>> m_positions;
  std::vector<Triangle> m_triangles;
  std::vector<std::uint32_t> m_order;
  std::vector<Node> m_nodes;
};

}  // namespace tissue::subsurface
