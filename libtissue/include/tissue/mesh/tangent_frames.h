#pragma once
/// \file
/// Per-vertex tangent frames from the UV parameterisation, for normal mapping and for the
/// tangent-space projections of subsurface texture mapping (François et al. §2.1, Fig. 6).

#include <cstdint>
#include <span>

#include "tissue/core/types.h"

namespace tissue::mesh {

/// Tangent frames (T, w): T is unit, orthogonal to the vertex normal N and points along
/// increasing u; the bitangent is B = w * cross(N, T) with w = +1 or -1 (handedness), and
/// points along increasing v. Per-triangle UV gradients are accumulated per render vertex
/// (angle-weighted). Across a UV seam (render vertices sharing a geometric vertex) the copies
/// whose charts are oriented alike (same handedness, u and v directions within 45 degrees,
/// e.g. a cylinder's wrap-around seam) pool their gradients and get the same frame, so normal
/// mapping shows no seam; copies in rotated or mirrored charts keep their own frames.
/// \param positions  #V render-vertex positions, mm
/// \param uvs        #V texture coordinates
/// \param triangles  #F triangles indexing the render vertices
/// \param normals    #V unit normals
/// \param tangents   #V output (T.xyz, w)
/// \param geometricIndex  #V geometric vertex of each render vertex, or empty (no seams)
void computeTangentFrames(std::span<const Float3> positions, std::span<const Float2> uvs,
                          std::span<const Triangle> triangles, std::span<const Float3> normals,
                          std::span<Float4> tangents, std::span<const std::uint32_t> geometricIndex = {});

}  // namespace tissue::mesh
