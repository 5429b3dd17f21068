#pragma once
/// \file
/// Inspection through VTK: fields on the mesh written as VTK XML PolyData (.vtp) for ParaView.
/// VTK stays inside src/inspect; this header speaks plain arrays.

#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "tissue/core/result.h"
#include "tissue/core/types.h"

namespace tissue::inspect {

/// One per-vertex field: `components` floats per vertex, interleaved.
struct VertexField {
  std::string name;               ///< array name shown in ParaView (put the unit in it, e.g. "offset_mm")
  int components = 1;             ///< 1 (scalar), 3 (vector) or 4
  std::span<const float> values;  ///< #V * components floats
};

/// Wraps a span of Float3/Float4 as a field without copying.
template <class T>
VertexField fieldOf(std::string name, std::span<const T> data) {
  static_assert(sizeof(T) % sizeof(float) == 0);
  return {std::move(name), int(sizeof(T) / sizeof(float)),
          std::span<const float>(reinterpret_cast<const float*>(data.data()),
                                 data.size() * sizeof(T) / sizeof(float))};
}

/// Whether the library was built with VTK (TISSUE_WITH_VTK); without it every export and chart
/// is one Error saying so.
bool builtWithVtk();

/// Writes a triangle mesh with per-vertex fields to `path` (.vtp), atomically.
/// \param positions  #V positions, mm
/// \param triangles  #F triangles
/// \param fields     per-vertex arrays; each must hold #V * components values
Result<void> writeVtp(const std::filesystem::path& path, std::span<const Float3> positions,
                      std::span<const Triangle> triangles, const std::vector<VertexField>& fields);

}  // namespace tissue::inspect
