#pragma once
// The OpenMesh adapter's reading half: OpenMesh's format readers (OFF, STL) feed a
// raw importer that records exactly what the file says - points, polygons, per-corner and
// per-vertex texture coordinates - without OpenMesh's topology checks, which silently drop
// non-manifold faces. Validation then names each defect (validate_mesh.cpp).

#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "tissue/core/result.h"

namespace tissue::mesh::detail {

/// What a mesh file contains, in file order.
struct RawMesh {
  std::vector<std::array<float, 3>> points;
  std::vector<std::vector<int>> polygons;                    ///< 0-based point indices
  std::vector<std::vector<std::array<float, 2>>> cornerUvs;  ///< per polygon; empty if none
  std::vector<std::array<float, 2>> vertexUvs;               ///< per point; empty if none
  std::vector<int> polygonLines;   ///< per polygon: 1-based line in the file, or empty if unknown
  std::vector<std::string> notes;  ///< what the reader skipped, one warning line each
};

/// Reads `path`: OBJ and PLY with the project's readers (obj_reader.cpp, ply_reader.cpp), OFF
/// and STL with OpenMesh's readers.
Result<RawMesh> readRawMesh(const std::filesystem::path& path);

/// The strict OBJ reader: every defect reported with its line number.
Result<RawMesh> readObj(const std::filesystem::path& path);

/// The PLY reader (ASCII and binary): faces, triangle strips (-1 restarts), every other element
/// and property skipped by its declared type; declared counts checked against the file size.
Result<RawMesh> readPly(const std::filesystem::path& path);

/// Appends the triangles of one triangle strip (PLY tristrips, VTK TRIANGLE_STRIPS) to `out`:
/// triangle i is (s[i-2], s[i-1], s[i]), every second one reversed so all keep the strip's
/// orientation; triangles repeating an index (joins between strips) are skipped. `line` > 0 is
/// recorded as each triangle's line.
void appendStripTriangles(const std::vector<int>& strip, int line, RawMesh& out);

}  // namespace tissue::mesh::detail
