#pragma once
/// \file
/// What the per-frame shading update needs of a mesh that never changes while it deforms:
/// which triangle corners meet at each vertex, the UV-parameterisation constants of each
/// triangle, and which render vertices are seam copies of one geometric vertex. Built once,
/// so the frame loop gathers over plain arrays and builds no hash maps.

#include <cstdint>
#include <span>
#include <vector>

#include "tissue/core/types.h"

namespace tissue::mesh {

/// Compressed vertex -> incident-corner lists: vertex v's corners are
/// corners[offsets[v] .. offsets[v+1]), in ascending order. Corner c is vertex c % 3 of
/// triangle c / 3. Summing per-corner terms in this order reproduces a scatter over the
/// triangles in index order bit for bit, whatever the number of threads.
struct VertexCorners {
  std::vector<std::uint32_t> offsets;  ///< #V + 1
  std::vector<std::uint32_t> corners;  ///< corner indices 3 t + k
  std::size_t vertexCount() const { return offsets.empty() ? 0 : offsets.size() - 1; }
};

/// The corners of `triangles` around each of `vertexCount` vertices. Triangles with
/// `keepTriangle[t] == 0` are left out (all are kept when `keepTriangle` is empty).
VertexCorners buildVertexCorners(std::span<const Triangle> triangles, std::size_t vertexCount,
                                 std::span<const std::uint8_t> keepTriangle = {});

/// A triangle's UV edges (s1, t1) = uv1 - uv0, (s2, t2) = uv2 - uv0 and r = 1 / det, from
/// which its UV gradients dP/du, dP/dv follow for any positions (Lengyel 2001).
struct UvBasis {
  float s1 = 0.0f, t1 = 0.0f;  ///< unitless
  float s2 = 0.0f, t2 = 0.0f;  ///< unitless
  float r = 0.0f;              ///< 1 / (s1 t2 - s2 t1); 0 when the triangle has no UV area
  bool hasUvArea = false;      ///< |det| >= 1e-20: the triangle carries gradient information
};

/// Everything per-frame-invariant that tangent frames need of a render mesh.
struct TangentTopology {
  VertexCorners corners;                   ///< render vertex -> corners of triangles with UV area
  std::vector<UvBasis> uvBases;            ///< #F
  std::vector<std::uint32_t> copyOffsets;  ///< #G + 1: geometric vertex g owns copies[copyOffsets[g]..[g+1])
  std::vector<std::uint32_t> copies;       ///< #V render vertices, grouped by geometric vertex, ascending
  std::size_t groupCount() const { return copyOffsets.empty() ? 0 : copyOffsets.size() - 1; }
};

/// Builds the tangent topology of a render mesh.
/// \param uvs        #V texture coordinates
/// \param triangles  #F triangles indexing the render vertices
/// \param geometricIndex  #V geometric vertex of each render vertex, or empty (each render
///                        vertex is its own group: no seams)
TangentTopology buildTangentTopology(std::span<const Float2> uvs, std::span<const Triangle> triangles,
                                     std::span<const std::uint32_t> geometricIndex = {});

}  // namespace tissue::mesh
