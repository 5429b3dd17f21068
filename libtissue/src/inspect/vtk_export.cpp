// The VTK adapter: VTK headers are included here and nowhere else in the library.
#include "tissue/inspect/vtk_export.h"

#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include "vtk_io.h"

namespace tissue::inspect {

bool builtWithVtk() {
  return true;
}

Result<void> writeVtp(const std::filesystem::path& path, std::span<const Float3> positions,
                      std::span<const Triangle> triangles, const std::vector<VertexField>& fields) {
  const std::string where = "cannot write '" + path.string() + "': ";
  for (const auto& f : fields) {
    if (f.components < 1 || f.values.size() != positions.size() * std::size_t(f.components))
      return Error{where + "field '" + f.name + "' has " + std::to_string(f.values.size()) + " values for " +
                   std::to_string(positions.size()) + " vertices x " + std::to_string(f.components) +
                   " components"};
  }
  vtkNew<vtkPoints> points;
  points->SetDataTypeToFloat();
  points->SetNumberOfPoints(vtkIdType(positions.size()));
  for (std::size_t i = 0; i < positions.size(); ++i)
    points->SetPoint(vtkIdType(i), double(positions[i].x), double(positions[i].y), double(positions[i].z));
  vtkNew<vtkCellArray> cells;
  for (const auto& t : triangles) {
    const vtkIdType ids[3] = {vtkIdType(t[0]), vtkIdType(t[1]), vtkIdType(t[2])};
    cells->InsertNextCell(3, ids);
  }
  vtkNew<vtkPolyData> poly;
  poly->SetPoints(points);
  poly->SetPolys(cells);
  for (const auto& f : fields) {
    vtkNew<vtkFloatArray> array;
    array->SetName(f.name.c_str());
    array->SetNumberOfComponents(f.components);
    array->SetNumberOfTuples(vtkIdType(positions.size()));
    std::copy(f.values.begin(), f.values.end(), array->GetPointer(0));
    poly->GetPointData()->AddArray(array);
  }
  return writeXmlAtomic(poly, path);
}

}  // namespace tissue::inspect
