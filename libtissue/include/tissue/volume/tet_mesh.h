#pragma once
/// \file
/// Tetrahedral volume meshes: loading legacy VTK (.vtk), VTK XML (.vtu) and Gmsh (.msh) files
/// with validation, and their geometry (volumes, boundary). Plain arrays only: VTK stays inside
/// the .vtk/.vtu reader, which is compiled only with TISSUE_WITH_VTK.

#include <cstddef>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "tissue/core/result.h"
#include "tissue/core/types.h"

namespace tissue::volume {

/// A tetrahedral mesh: positions and positively oriented tets.
struct TetMesh {
  std::vector<Float3> positions;  ///< mm, #vertices
  std::vector<Tet> tets;          ///< vertex indices, each with positive volume, #tets
};

/// What the caller needs of the file.
struct TetLoadOptions {
  float scaleToMm = 1.0f;  ///< mm per file unit (the SOFA meshes state no units)
};

/// What the loader skipped or changed.
struct TetLoadReport {
  std::size_t ignoredCells = 0;          ///< cells that are not 4-node tets (triangles, lines, ...)
  std::size_t reorientedTets = 0;        ///< inverted tets (negative volume) whose order was fixed
  std::size_t unreferencedVertices = 0;  ///< vertices that belong to no tet
  std::vector<std::string> warnings;     ///< one line each, naming the file
};

/// Loads `path`: .vtk (legacy VTK unstructured grid), .vtu (VTK XML unstructured grid) or .msh
/// (Gmsh v1, v2 or v4.1, ASCII or binary). A .vtk file with XML content (VTK XML unstructured
/// grid) is read by VTK's XML reader; one that holds a surface (POLYDATA) is an Error pointing to
/// the surface loader. VTK's own messages become one Error line naming the file. Declared counts
/// are checked against the file size before anything is allocated for them.
/// Only 4-node tets are kept; other cells are counted in `report`.
/// Fails, naming the file and the element (1-based, in file order), on non-finite coordinates,
/// indices out of range, a tet repeating a vertex, a degenerate (zero-volume) tet, or no tets.
/// Inverted tets are re-oriented (two vertices swapped) and counted. A library built without VTK
/// (TISSUE_WITH_VTK=OFF) reads .msh only: a .vtk/.vtu file is then one Error saying so and how to
/// convert it to Gmsh .msh.
Result<TetMesh> loadTetMesh(const std::filesystem::path& path, const TetLoadOptions& options = {},
                            TetLoadReport* report = nullptr);

/// True when `path` has an extension loadTetMesh reads (.vtk, .vtu, .msh), except a .vtk file
/// whose header says it holds a surface (see isVtkSurfacePath in vtk_surface.h): that one goes to
/// the surface loader.
bool isTetMeshPath(const std::filesystem::path& path);

/// Signed volume of tet `t` in mm^3: det(b - a, c - a, d - a) / 6.
double signedTetVolume(std::span<const Float3> positions, const Tet& t);

/// Sum of the tets' volumes in mm^3.
double totalVolume(const TetMesh& mesh);

/// The faces that belong to exactly one tet, oriented outwards (counter-clockwise seen from
/// outside), as triangles over the mesh's vertices.
std::vector<Triangle> boundaryTriangles(const TetMesh& mesh);

/// Volume enclosed by a closed, outward-oriented triangle surface in mm^3, by the divergence
/// theorem: sum over triangles of a . (b x c) / 6.
double enclosedVolume(std::span<const Float3> positions, std::span<const Triangle> triangles);

}  // namespace tissue::volume
