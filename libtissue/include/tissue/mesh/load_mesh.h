#pragma once
/// \file
/// Loading triangle meshes (OBJ, PLY, OFF, STL, VTK surfaces), with validation: every defect is
/// reported as one Error naming the file and the element, or (lenient mode) repaired with one
/// warning line per kind of repair.

#include <filesystem>
#include <string>
#include <vector>

#include "tissue/core/result.h"
#include "tissue/core/surface_mesh.h"

namespace tissue::mesh {

/// What the caller needs of the file.
struct LoadOptions {
  bool requireUvs = false;  ///< fail when the file has no texture coordinates
  float scaleToMm = 1.0f;   ///< mm per file unit (the SOFA meshes state no units)
  /// Strict: zero-area faces, faces with fewer than three vertices, non-manifold edges, bow-tie
  /// vertices, inconsistently oriented faces and unused vertices are errors. Lenient (the
  /// default): they are dropped or repaired (as MeshLab and VTK open such files) and each kind is
  /// reported as one warning line with counts in LoadReport, because real exported organ meshes
  /// carry collapsed slivers, stray line elements and a few non-manifold spots. Repeated indices,
  /// out-of-range indices and NaN/Inf are errors in both modes.
  bool strict = false;
};

/// What the loader changed or noticed (lenient mode).
struct LoadReport {
  std::size_t droppedZeroAreaFaces = 0;   ///< triangles with three distinct but collinear vertices
  std::size_t droppedLineElements = 0;    ///< faces with fewer than three vertices
  std::size_t splitNonManifoldEdges = 0;  ///< edges shared by more than two faces, split
  std::size_t splitBowTieVertices = 0;    ///< vertices joining separate sheets, split
  std::size_t flippedFaces = 0;           ///< faces reversed to agree with their neighbours
  std::size_t droppedUnusedVertices = 0;  ///< file vertices no face uses
  std::vector<std::string> warnings;      ///< one line each, naming the file and the element
};

/// Loads `path` (.obj, .ply including triangle strips, .off, .stl, and VTK surfaces: a .vtk with
/// DATASET POLYDATA or XML PolyData content, or .vtp, read through the volume module's VTK
/// adapter; polygons are fan-triangulated, strips split) into render vertices
/// split at UV seams. Rejects NaN/Inf coordinates, out-of-range indices, faces repeating a
/// vertex, declared counts the file size cannot hold, and missing UVs when `options.requireUvs`;
/// lenient mode repairs non-manifold edges, bow-tie vertices and misoriented faces and drops
/// unused vertices (strict refuses them); the error names the file and the vertex or face
/// (1-based, in file order) and says how to fix it.
Result<SurfaceMesh> loadMesh(const std::filesystem::path& path, const LoadOptions& options = {},
                             LoadReport* report = nullptr);

/// Checks an in-memory mesh the same way the loader does; `source` names it in errors.
Result<void> validateMesh(const SurfaceMesh& mesh, const std::string& source);

/// Writes `mesh` as OBJ (positions, UVs when present, faces) atomically.
Result<void> writeObj(const std::filesystem::path& path, const SurfaceMesh& mesh);

}  // namespace tissue::mesh
