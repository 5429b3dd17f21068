#pragma once
/// \file
/// Angle-weighted vertex normals (Thürmer and Wüthrich 1998): each incident triangle
/// contributes its unit normal weighted by its interior angle at the vertex, which makes the
/// result independent of how the surface is triangulated.

#include <span>

#include "tissue/core/types.h"

namespace tissue::mesh {

/// Angle-weighted unit normals.
/// \param positions  #V positions, mm
/// \param triangles  #F triangles indexing `positions`
/// \param normals    #V output unit normals; a vertex with no (non-degenerate) triangle gets (0,0,1)
void computeVertexNormals(std::span<const Float3> positions, std::span<const Triangle> triangles,
                          std::span<Float3> normals);

}  // namespace tissue::mesh
