#pragma once
/// \file
/// The plain-array triangle mesh every module speaks: the mesh module produces it, the
/// simulator deforms its positions, the renderer uploads it. No library types appear here.

#include <cstdint>
#include <vector>

#include "tissue/core/types.h"

namespace tissue {

/// A triangle mesh split into render vertices at UV seams.
///
/// A geometric vertex (one point of the surface) appears as several render vertices where
/// the UV atlas has a seam; `geometricIndex` maps each render vertex back to its geometric
/// vertex, so shading quantities that must not break at seams (normals, planes) are computed
/// once per geometric vertex and shared.
struct SurfaceMesh {
  std::vector<Float3> positions;              ///< mm; #render vertices
  std::vector<Float2> uvs;                    ///< unitless; empty, or #render vertices
  std::vector<Triangle> triangles;            ///< render-vertex indices, counter-clockwise outside
  std::vector<std::uint32_t> geometricIndex;  ///< #render vertices; geometric vertex of each
  std::uint32_t geometricVertexCount = 0;     ///< number of distinct geometric vertices
  /// #geometric vertices when loaded from a file: each geometric vertex's 0-based index among
  /// the file's vertices (geometric vertices are numbered in order of first use); else empty.
  std::vector<std::uint32_t> geometricSourceIndex;

  bool hasUvs() const { return !uvs.empty() && uvs.size() == positions.size(); }
  std::size_t vertexCount() const { return positions.size(); }
  std::size_t triangleCount() const { return triangles.size(); }
};

/// Gathers geometric-vertex values to render vertices: out[i] = geo[mesh.geometricIndex[i]].
template <class T>
void gatherToRenderVertices(const SurfaceMesh& mesh, const std::vector<T>& geo, std::vector<T>& out) {
  out.resize(mesh.positions.size());
  for (std::size_t i = 0; i < out.size(); ++i)
    out[i] = geo[mesh.geometricIndex[i]];
}

}  // namespace tissue
