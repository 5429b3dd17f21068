#include "vtk_io.h"

#include <vtkDataSetAttributes.h>
#include <vtkFloatArray.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkRenderWindow.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkWindowToImageFilter.h>
#include <vtkXMLPolyDataWriter.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <algorithm>
#include <random>

namespace tissue::inspect {

Result<void> writeXmlAtomic(vtkDataObject* data, const std::filesystem::path& path) {
  const std::string where = "cannot write '" + path.string() + "': ";
  vtkSmartPointer<vtkXMLWriter> writer;
  if (vtkPolyData::SafeDownCast(data))
    writer = vtkSmartPointer<vtkXMLPolyDataWriter>::New();
  else if (vtkUnstructuredGrid::SafeDownCast(data))
    writer = vtkSmartPointer<vtkXMLUnstructuredGridWriter>::New();
  else
    return Error{where + "only PolyData (.vtp) and UnstructuredGrid (.vtu) are written"};
  std::error_code ec;
  std::filesystem::create_directories(path.has_parent_path() ? path.parent_path() : ".", ec);
  std::string tmpName(".");  // appended, not "." + string: g++ 12 reports a false -Wrestrict
  tmpName.append(path.filename().string()).append(".tmp").append(std::to_string(std::random_device{}()));
  const auto tmp = path.parent_path() / tmpName;
  writer->SetFileName(tmp.c_str());
  writer->SetInputDataObject(data);
  // Appended raw binary, LZ4-compressed: the fastest of VTK's XML encodings that ParaView reads
  // (zlib, the default, costs several times the write; base64 another third in size).
  writer->SetDataModeToAppended();
  writer->EncodeAppendedDataOff();
  writer->SetCompressorTypeToLZ4();
  if (writer->Write() != 1) {
    std::filesystem::remove(tmp, ec);
    return Error{where + "VTK's writer failed; check the folder is writable and the disk not full"};
  }
  std::filesystem::rename(tmp, path, ec);
  if (ec) return Error{where + ec.message()};
  return {};
}

vtkSmartPointer<vtkFloatArray> floatArray(const std::string& name, int components,
                                          std::span<const float> values) {
  auto array = vtkSmartPointer<vtkFloatArray>::New();
  array->SetName(name.c_str());
  array->SetNumberOfComponents(components);
  array->SetNumberOfTuples(vtkIdType(values.size() / std::size_t(components)));
  std::copy(values.begin(), values.end(), array->GetPointer(0));
  return array;
}

void addArray(vtkDataSetAttributes* attributes, const std::string& name, std::span<const Float3> values) {
  attributes->AddArray(
      floatArray(name, 3, {reinterpret_cast<const float*>(values.data()), values.size() * 3}));
}

void addArray(vtkDataSetAttributes* attributes, const std::string& name, std::span<const Float4> values) {
  attributes->AddArray(
      floatArray(name, 4, {reinterpret_cast<const float*>(values.data()), values.size() * 4}));
}

void addArray(vtkDataSetAttributes* attributes, const std::string& name, std::span<const float> values) {
  attributes->AddArray(floatArray(name, 1, values));
}

vtkSmartPointer<vtkPoints> pointsOf(std::span<const Float3> positions) {
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToFloat();
  points->SetNumberOfPoints(vtkIdType(positions.size()));
  for (std::size_t i = 0; i < positions.size(); ++i)
    points->SetPoint(vtkIdType(i), double(positions[i].x), double(positions[i].y), double(positions[i].z));
  return points;
}

std::vector<std::uint8_t> renderToPng(vtkRenderWindow* window) {
  window->Render();
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ReadFrontBufferOff();
  grab->Update();
  vtkNew<vtkPNGWriter> writer;
  writer->WriteToMemoryOn();
  writer->SetInputConnection(grab->GetOutputPort());
  writer->Write();
  vtkUnsignedCharArray* bytes = writer->GetResult();
  if (!bytes || bytes->GetNumberOfValues() == 0) return {};
  return {bytes->GetPointer(0), bytes->GetPointer(0) + bytes->GetNumberOfValues()};
}

}  // namespace tissue::inspect
