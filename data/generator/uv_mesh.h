#pragma once
/// \file
/// The generator's mesh: positions and per-corner texture coordinates, exactly what an OBJ file
/// with `v`, `vt` and `f v/vt` lines holds. A vertex on a UV seam has one position and several
/// texture coordinates, so the geometric mesh stays watertight.

#include <string>
#include <vector>

#include "tissue/core/types.h"

namespace tissue::datagen {

/// A triangle mesh with a UV atlas (OBJ-style separate position and UV indices).
struct UvMesh {
  std::vector<Float3> positions;      ///< mm
  std::vector<Float2> uvs;            ///< in [0, 1]^2, v up (OBJ convention: v = 0 is the image's last row)
  std::vector<Triangle> triangles;    ///< indices into `positions`, counter-clockwise seen from outside
  std::vector<Triangle> uvTriangles;  ///< per-corner indices into `uvs`, same order as `triangles`
};

/// Formats `mesh` as OBJ text: a `#` comment per line of `header`, then `v` lines ("%.5f", mm),
/// `vt` lines ("%.6f") and `f v/vt` lines (1-based). The output is byte-for-byte reproducible.
std::string toObj(const UvMesh& mesh, const std::string& header);

}  // namespace tissue::datagen
