#pragma once
// What a volume reader hands to validation: the file's points and its 4-node tets as written,
// before any check. Private to the volume module.

#include <array>
#include <cstdint>
#include <filesystem>
#include <vector>

#include "tissue/core/result.h"
#include "tissue/volume/vtk_surface.h"

namespace tissue::volume::detail {

/// One tet as the file writes it.
struct RawTet {
  std::array<std::int64_t, 4> v{};  ///< 0-based vertex indices, unchecked
  std::size_t element = 0;          ///< 1-based position of the cell in the file's cell list
};

/// The file's content, unchecked.
struct RawVolume {
  std::vector<std::array<double, 3>> points;  ///< file units
  std::vector<RawTet> tets;
  std::size_t ignoredCells = 0;  ///< cells that are not 4-node tets
};

/// What a .vtk file holds, from its first bytes: a legacy DATASET line, or XML content (which
/// VTK's legacy reader refuses as "Unrecognized file type").
enum class VtkContent { LegacyGrid, LegacySurface, XmlGrid, XmlSurface, Unknown };
VtkContent sniffVtk(const std::filesystem::path& path);

/// Bounded memory and VTK's own robustness: the POINTS count of a legacy .vtk header against
/// the file size, and (text files) each cell section's declared integers, before VTK reads it.
Result<void> checkLegacyVtkCounts(const std::filesystem::path& path);
/// The same for VTK XML (.vtu, .vtp, XML content in a .vtk): every NumberOf... attribute must be
/// a plain non-negative integer that the file could hold (VTK's XML reader takes them as they
/// are: a 100-digit NumberOfComponents ran for minutes, found by the VTU fuzz target).
Result<void> checkXmlVtkCounts(const std::filesystem::path& path);

/// Legacy VTK unstructured grid (.vtk) through vtkUnstructuredGridReader.
Result<RawVolume> readLegacyVtk(const std::filesystem::path& path);
/// VTK XML unstructured grid (.vtu) through vtkXMLUnstructuredGridReader.
Result<RawVolume> readVtu(const std::filesystem::path& path);
/// A VTK surface: legacy POLYDATA (vtkPolyDataReader) or, when `xml`, VTK XML PolyData
/// (vtkXMLPolyDataReader).
Result<VtkSurface> readVtkPolyData(const std::filesystem::path& path, bool xml);
/// Gmsh .msh, ASCII v1 ($NOD/$ELM), v2 and v4.1 ($Nodes/$Elements).
Result<RawVolume> readGmsh(const std::filesystem::path& path);

}  // namespace tissue::volume::detail
