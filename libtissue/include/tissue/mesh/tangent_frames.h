#pragma once
/// \file
/// Per-vertex tangent frames from the UV parameterisation, for normal mapping and for the
/// tangent-space projections of subsurface texture mapping (François et al. §2.1, Fig. 6).

#include <cstddef>
#include <cstdint>
#include <span>

#include "tissue/core/types.h"
#include "tissue/mesh/shading_topology.h"
#include "tissue/mesh/triangle_geometry.h"

namespace tissue::mesh {

class WorkerPool;

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

/// The same frames from precomputed topology and per-frame triangle geometry, for the render
/// vertices of seam groups (geometric vertices) [firstGroup, lastGroup). Each vertex sums its
/// corners in ascending order and each group pools in ascending vertex order, so the result
/// equals the function above bit for bit, however the groups are split over threads.
/// \param geometry  #F from computeTriangleGeometry with `topology.uvBases`
/// \param topology  from buildTangentTopology of the same render mesh
/// \param normals   #V unit normals
/// \param tangents  #V output (T.xyz, w)
void computeTangentFramesOfGroups(std::span<const TriangleGeometry> geometry, const TangentTopology& topology,
                                  std::span<const Float3> normals, std::size_t firstGroup,
                                  std::size_t lastGroup, std::span<Float4> tangents);

/// All render vertices' frames from precomputed topology, on `pool` when given.
void computeTangentFrames(std::span<const TriangleGeometry> geometry, const TangentTopology& topology,
                          std::span<const Float3> normals, std::span<Float4> tangents,
                          WorkerPool* pool = nullptr);

}  // namespace tissue::mesh
