#pragma once
// Topology repairs of the lenient loader (issue 14): what MeshLab and VTK open, the loader opens
// too, after making the surface a consistently oriented 2-manifold. Each repair is counted so the
// loader can report it as one warning line; strict loading skips them and validation refuses.

#include <cstdint>
#include <vector>

#include "tissue/core/types.h"

namespace tissue::mesh::detail {

/// What repairTopology changed.
struct TopologyRepairs {
  std::size_t nonManifoldEdges = 0;  ///< edges shared by more than two faces
  std::size_t detachedFaces = 0;     ///< faces beyond the first two on such an edge, detached from it
  std::size_t bowTieVertices = 0;    ///< vertices whose faces formed two or more separate fans
  std::size_t addedVertices = 0;     ///< copies made by both splits
  std::size_t flippedFaces = 0;      ///< faces reversed to agree with their neighbours
};

/// Repairs `triangles` over `points` in place, in this order:
/// 1. a face whose edge already has two faces gets its own copies of that edge's two vertices
///    (the edge is split; faces are taken in file order, so the first two keep it);
/// 2. a vertex whose faces form k > 1 edge-connected fans is split into k vertices;
/// 3. in each edge-connected component the faces are oriented like their neighbours, flipping
///    the minority. A non-orientable component (a Moebius strip) is left for validation.
/// Copies are appended to `points`; `pointSource` (one entry per point, grown alongside) gives
/// the original point each one copies.
TopologyRepairs repairTopology(std::vector<Float3>& points, std::vector<std::uint32_t>& pointSource,
                               std::vector<Triangle>& triangles);

}  // namespace tissue::mesh::detail
