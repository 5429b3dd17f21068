// The VTK adapter: VTK headers are included here and nowhere else in the library.
#include "tissue/inspect/vtk_export.h"

#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkXMLPolyDataWriter.h>

#include <random>

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
  // Write beside the target, then rename: an interrupted export never replaces a good file.
  std::error_code ec;
  std::filesystem::create_directories(path.has_parent_path() ? path.parent_path() : ".", ec);
  std::string tmpName(".");  // appended, not "." + string: g++ 12 reports a false -Wrestrict
  tmpName.append(path.filename().string()).append(".tmp").append(std::to_string(std::random_device{}()));
  const auto tmp = path.parent_path() / tmpName;
  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetFileName(tmp.c_str());
  writer->SetInputData(poly);
  writer->SetDataModeToBinary();
  if (writer->Write() != 1) {
    std::filesystem::remove(tmp, ec);
    return Error{where + "VTK's writer failed; check the folder is writable and the disk not full"};
  }
  std::filesystem::rename(tmp, path, ec);
  if (ec) return Error{where + ec.message()};
  return {};
}

}  // namespace tissue::inspect
