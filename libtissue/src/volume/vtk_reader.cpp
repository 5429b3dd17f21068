// The VTK adapter of the volume module: legacy .vtk and XML .vtu unstructured grids. The only
// file of the module that includes VTK.
#include <vtkCallbackCommand.h>
#include <vtkCellType.h>
#include <vtkCommand.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkUnstructuredGrid.h>
#include <vtkUnstructuredGridReader.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <string>
#include <system_error>

#include "raw_volume.h"

namespace tissue::volume::detail {
namespace {

/// Collects VTK's error and warning events instead of letting VTK print them, so that a bad
/// file becomes one Error (the reader never throws and only logs).
void collectMessage(vtkObject*, unsigned long, void* clientData, void* callData) {
  auto* messages = static_cast<std::string*>(clientData);
  if (callData && messages->empty()) *messages = static_cast<const char*>(callData);
}

/// Copies a read grid's points and its VTK_TETRA cells; other cells are counted.
RawVolume fromGrid(vtkUnstructuredGrid& grid) {
  RawVolume raw;
  vtkPoints* points = grid.GetPoints();
  const vtkIdType pointCount = points ? points->GetNumberOfPoints() : 0;
  raw.points.resize(static_cast<std::size_t>(pointCount));
  for (vtkIdType p = 0; p < pointCount; ++p) {
    double x[3];
    points->GetPoint(p, x);
    raw.points[static_cast<std::size_t>(p)] = {x[0], x[1], x[2]};
  }
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < grid.GetNumberOfCells(); ++c) {
    grid.GetCellPoints(c, ids);
    if (grid.GetCellType(c) != VTK_TETRA || ids->GetNumberOfIds() != 4) {
      ++raw.ignoredCells;
      continue;
    }
    RawTet tet;
    for (int k = 0; k < 4; ++k)
      tet.v[static_cast<std::size_t>(k)] = ids->GetId(k);
    tet.element = static_cast<std::size_t>(c) + 1;
    raw.tets.push_back(tet);
  }
  return raw;
}

/// Runs `reader` on `path` with VTK's messages captured; fails on a message or an empty grid.
template <class Reader>
Result<RawVolume> readWith(Reader& reader, const std::filesystem::path& path, const char* kind) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    return Error{path.string() + ": no such file; check the path"};
  std::string message;
  vtkNew<vtkCallbackCommand> observer;
  observer->SetCallback(collectMessage);
  observer->SetClientData(&message);
  reader.AddObserver(vtkCommand::ErrorEvent, observer);
  reader.AddObserver(vtkCommand::WarningEvent, observer);
  reader.SetFileName(path.c_str());
  reader.Update();
  vtkUnstructuredGrid* grid = reader.GetOutput();
  if (!message.empty() || !grid)
    return Error{path.string() + ": VTK could not read it as " + kind + ": " +
                 (message.empty() ? std::string("no output") : message) + "; check the file"};
  return fromGrid(*grid);
}

}  // namespace

Result<RawVolume> readLegacyVtk(const std::filesystem::path& path) {
  vtkNew<vtkUnstructuredGridReader> reader;
  return readWith(*reader, path, "a legacy VTK unstructured grid (DATASET UNSTRUCTURED_GRID)");
}

Result<RawVolume> readVtu(const std::filesystem::path& path) {
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  return readWith(*reader, path, "a VTK XML unstructured grid");
}

}  // namespace tissue::volume::detail
