#pragma once
/// \file
/// Private helpers of the VTK adapter: VTK XML files written atomically, plain arrays as VTK
/// arrays, and a render window's image as PNG bytes.

#include <vtkSmartPointer.h>

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "tissue/core/result.h"
#include "tissue/core/types.h"

class vtkDataObject;
class vtkDataSetAttributes;
class vtkFloatArray;
class vtkPoints;
class vtkRenderWindow;

namespace tissue::inspect {

/// Writes `data` with VTK's XML writer for its type (.vtp PolyData, .vtu UnstructuredGrid),
/// binary, beside the target then renamed: an interrupted write never replaces a good file.
Result<void> writeXmlAtomic(vtkDataObject* data, const std::filesystem::path& path);

/// `components` floats per tuple as a named VTK array.
vtkSmartPointer<vtkFloatArray> floatArray(const std::string& name, int components,
                                          std::span<const float> values);
/// Adds per-tuple arrays of Float3 / Float4 / float to `attributes` (point or cell data).
void addArray(vtkDataSetAttributes* attributes, const std::string& name, std::span<const Float3> values);
void addArray(vtkDataSetAttributes* attributes, const std::string& name, std::span<const Float4> values);
void addArray(vtkDataSetAttributes* attributes, const std::string& name, std::span<const float> values);

/// Positions (mm) as VTK points (float).
vtkSmartPointer<vtkPoints> pointsOf(std::span<const Float3> positions);

/// Renders `window` and returns its back buffer as PNG bytes (empty when VTK produced none).
std::vector<std::uint8_t> renderToPng(vtkRenderWindow* window);

}  // namespace tissue::inspect
