#pragma once
/// \file
/// Per-triangle quantities of one frame that vertex normals and tangent frames share: the
/// unit face normal, the interior angle at each corner (the weights of Thürmer and Wüthrich
/// 1998) and the unit UV gradients (Lengyel 2001). Computed once per triangle and gathered
/// per vertex, instead of once per incident corner and scattered.

#include <array>
#include <cstddef>
#include <span>

#include "tissue/core/types.h"
#include "tissue/mesh/shading_topology.h"

namespace tissue::mesh {

/// One triangle's shading geometry at the current positions.
struct TriangleGeometry {
  Float3 normal;                ///< unit face normal (0 for a degenerate triangle)
  std::array<float, 3> angles;  ///< interior angle at corners 0, 1, 2, rad
  Float3 dPdu;                  ///< unit dP/du (0 without UV bases or UV area)
  Float3 dPdv;                  ///< unit dP/dv (0 without UV bases or UV area)
};

/// Computes triangles [first, last) of `out`.
/// \param positions  #V positions, mm
/// \param triangles  #F triangles indexing `positions`
/// \param uvBases    #F UV constants (buildTangentTopology), or empty: gradients are left 0
/// \param out        #F output
void computeTriangleGeometry(std::span<const Float3> positions, std::span<const Triangle> triangles,
                             std::span<const UvBasis> uvBases, std::size_t first, std::size_t last,
                             std::span<TriangleGeometry> out);

}  // namespace tissue::mesh
