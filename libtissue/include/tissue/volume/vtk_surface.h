#pragma once
/// \file
/// Surfaces in VTK files: a legacy .vtk with DATASET POLYDATA, or VTK XML PolyData content (in a
/// .vtk or .vtp file), read through the volume module's VTK adapter as plain arrays. The mesh
/// module's loader turns them into a SurfaceMesh (validation, repairs) like any other surface.

#include <array>
#include <cstdint>
#include <filesystem>
#include <vector>

#include "tissue/core/result.h"

namespace tissue::volume {

/// A VTK surface as the file writes it, unchecked.
struct VtkSurface {
  std::vector<std::array<double, 3>> points;        ///< file units
  std::vector<std::vector<std::int64_t>> polygons;  ///< POLYGONS cells, 0-based point ids
  std::vector<std::vector<std::int64_t>> strips;    ///< TRIANGLE_STRIPS cells, 0-based point ids
  std::size_t ignoredCells = 0;                     ///< VERTICES and LINES cells
};

/// True when `path` is a .vtk file whose header says it holds a surface (legacy DATASET
/// POLYDATA, or XML content of type PolyData), or a .vtp file. Reads only the first bytes; needs
/// no VTK.
bool isVtkSurfacePath(const std::filesystem::path& path);

/// Reads the surface of `path` (see isVtkSurfacePath). VTK's messages become one Error line
/// naming the file. Built without VTK: one Error saying how to convert the file.
Result<VtkSurface> readVtkSurface(const std::filesystem::path& path);

}  // namespace tissue::volume
