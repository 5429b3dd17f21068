#pragma once
/// \file
/// Angle-weighted vertex normals (Thürmer and Wüthrich 1998): each incident triangle
/// contributes its unit normal weighted by its interior angle at the vertex, which makes the
/// result independent of how the surface is triangulated.

#include <cstddef>
#include <span>

#include "tissue/core/types.h"
#include "tissue/mesh/shading_topology.h"
#include "tissue/mesh/triangle_geometry.h"

namespace tissue::mesh {

class WorkerPool;

/// Angle-weighted unit normals.
/// \param positions  #V positions, mm
/// \param triangles  #F triangles indexing `positions`
/// \param normals    #V output unit normals; a vertex with no (non-degenerate) triangle gets (0,0,1)
void computeVertexNormals(std::span<const Float3> positions, std::span<const Triangle> triangles,
                          std::span<Float3> normals);

/// The same normals from precomputed topology and per-frame triangle geometry, for vertices
/// [first, last): each vertex sums its corners' terms in ascending corner order, so the result
/// equals the function above bit for bit, however the vertices are split over threads.
/// \param geometry  #F from computeTriangleGeometry
/// \param corners   vertex -> corner lists of the same triangles (buildVertexCorners)
/// \param normals   #V output unit normals
void gatherVertexNormals(std::span<const TriangleGeometry> geometry, const VertexCorners& corners,
                         std::size_t first, std::size_t last, std::span<Float3> normals);

/// All vertices' normals from precomputed topology, on `pool` when given.
void computeVertexNormals(std::span<const TriangleGeometry> geometry, const VertexCorners& corners,
                          std::span<Float3> normals, WorkerPool* pool = nullptr);

}  // namespace tissue::mesh
