#pragma once
/// \file
/// What a mesh file holds, after validation (tissue-sim mesh-info): a surface (OBJ, PLY, OFF, STL)
/// or a tetrahedral volume (.vtk, .vtu, .msh), as a JSON object's text.

#include <filesystem>
#include <string>
#include <vector>

#include "tissue/core/result.h"

namespace tissue::studies {

/// How to load the file.
struct MeshDescriptionOptions {
  float scaleToMm = 1.0f;  ///< mm per file unit
  bool strict = false;     ///< surfaces: refuse what lenient mode repairs or drops (mesh::LoadOptions)
};

/// The description and the loader's warnings.
struct MeshDescription {
  /// A surface: vertices (geometric), render_vertices, faces, has_uvs, bbox_min and bbox_max (mm),
  /// units, dropped_zero_area_faces, dropped_line_elements, warnings. A volume: kind
  /// ("tetrahedral volume"), vertices, tets, volume_mm3, boundary_triangles, bbox_min and bbox_max
  /// (mm), units, ignored_cells, reoriented_tets, unreferenced_vertices, warnings.
  std::string json;
  std::vector<std::string> warnings;  ///< what lenient loading repaired or dropped
};

/// Loads `file` (a volume by its extension, volume::isTetMeshPath) and describes it; the error
/// names the file and what is wrong with it.
Result<MeshDescription> describeMeshFile(const std::filesystem::path& file,
                                         const MeshDescriptionOptions& options);

}  // namespace tissue::studies
