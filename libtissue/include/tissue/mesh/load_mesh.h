#pragma once
/// \file
/// Loading triangle meshes (OBJ, PLY, OFF, STL) through OpenMesh's readers, with strict
/// validation: every defect is reported as one Error naming the file and the element.

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

/// Loads `path` (.obj, .ply, .off, .stl; polygons are fan-triangulated) into render vertices
/// split at UV seams. Rejects NaN/Inf coordinates, out-of-range indices, degenerate and
/// non-manifold faces, and missing UVs when `options.requireUvs`; the error names the file
/// and the vertex or face (1-based, in file order) and says how to fix it.
Result<SurfaceMesh> loadMesh(const std::filesystem::path& path, const LoadOptions& options = {},
                             LoadReport* report = nullptr);

/// Checks an in-memory mesh the same way the loader does; `source` names it in errors.
Result<void> validateMesh(const SurfaceMesh& mesh, const std::string& source);

/// Writes `mesh` as OBJ (positions, UVs when present, faces) atomically.
Result<void> writeObj(const std::filesystem::path& path, const SurfaceMesh& mesh);

}  // namespace tissue::mesh
