#pragma once
/// \file
/// A small OBJ reader for the data tests (`v`, `vt`, `f v/vt` triangles only), independent of the
/// mesh module so the data can be checked on its own.

#include <filesystem>
#include <string>
#include <vector>

#include "tissue/core/result.h"
#include "tissue/core/types.h"

namespace tissue::datatest {

/// An OBJ mesh with separate position and UV indices (0-based).
struct ObjMesh {
  std::vector<Float3> positions;      ///< mm
  std::vector<Float2> uvs;            ///< unitless
  std::vector<Triangle> triangles;    ///< into positions
  std::vector<Triangle> uvTriangles;  ///< into uvs
};

/// Parses OBJ text; the error names the line.
Result<ObjMesh> parseObj(const std::string& text);

/// Reads and parses an OBJ file.
Result<ObjMesh> readObj(const std::filesystem::path& path);

}  // namespace tissue::datatest
