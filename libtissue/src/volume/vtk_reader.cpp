// The VTK adapter of the volume module: legacy .vtk and XML .vtu unstructured grids, and legacy
// and XML PolyData surfaces. The only file of the module that includes VTK.
#include <vtkCallbackCommand.h>
#include <vtkCellArray.h>
#include <vtkCellType.h>
#include <vtkCommand.h>
#include <vtkIdList.h>
#include <vtkLogger.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkOutputWindow.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataReader.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>
#include <vtkUnstructuredGridReader.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <sstream>
#include <string>
#include <system_error>

#include "raw_volume.h"

namespace tissue::volume::detail {
namespace {

/// VTK's messages are several lines ("ERROR: In ./IO/Legacy/vtkDataReader.cxx, line 567",
/// "vtkUnstructuredGridReader (0x55...): Unrecognized file type ...", blank lines). This keeps
/// the text: source-location lines and the "Class (0x...): " prefix are dropped, the rest joined.
std::string oneLine(const std::string& message) {
  std::istringstream in(message);
  std::string out, line;
  while (std::getline(in, line)) {
    while (!line.empty() && (line.back() == '\r' || line.back() == ' '))
      line.pop_back();
    if (line.empty()) continue;
    if (line.find(": In ") != std::string::npos && line.find(", line ") != std::string::npos) continue;
    if (const auto p = line.find(" (0x"); p != std::string::npos && p < line.find(' ') + 1) {
      const auto close = line.find("): ", p);
      if (close != std::string::npos) line = line.substr(close + 3);
    }
    out += (out.empty() ? "" : "; ") + line;
  }
  while (!out.empty() && (out.back() == '.' || out.back() == ' '))
    out.pop_back();  // the caller goes on with "; check the file"
  return out;
}

/// Collects VTK's error and warning events instead of letting VTK print them, so that a bad
/// file becomes one Error (the reader never throws and only logs).
void collectMessage(vtkObject*, unsigned long, void* clientData, void* callData) {
  auto* messages = static_cast<std::string*>(clientData);
  if (messages && callData && messages->empty()) *messages = oneLine(static_cast<const char*>(callData));
}

/// Messages that VTK objects without the reader's observer send (helper objects, generic
/// warnings such as "Error reading ascii data") go to the output window; this one keeps the
/// first instead of printing it.
class CapturingOutputWindow final : public vtkOutputWindow {
 public:
  static CapturingOutputWindow* New();
  vtkTypeMacro(CapturingOutputWindow, vtkOutputWindow) void DisplayText(const char* text) override {
    keep(text);
  }
  void DisplayErrorText(const char* text) override { keep(text); }
  void DisplayWarningText(const char* text) override { keep(text); }
  void DisplayGenericWarningText(const char* text) override { keep(text); }
  void DisplayDebugText(const char*) override {}
  const std::string& first() const { return m_first; }

 private:
  void keep(const char* text) {
    if (text && m_first.empty()) m_first = oneLine(text);
  }
  std::string m_first;
};
vtkStandardNewMacro(CapturingOutputWindow);

/// Installs a CapturingOutputWindow for one read and puts the previous window back. VTK 9 also
/// logs each error and warning macro to stderr through vtkLogger (a coloured line with the
/// source location), so stderr logging is off for the read and restored to the cutoff it had
/// (VTK has no getter for the stderr sink alone; with no log files this is the same). Both are
/// process-wide: reads on several threads at once would share them.
class OutputWindowScope {
 public:
  OutputWindowScope()
      : m_previous(vtkOutputWindow::GetInstance()), m_verbosity(vtkLogger::GetCurrentVerbosityCutoff()) {
    vtkOutputWindow::SetInstance(m_window);
    vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  }
  ~OutputWindowScope() {
    vtkLogger::SetStderrVerbosity(m_verbosity);
    vtkOutputWindow::SetInstance(m_previous);
  }
  OutputWindowScope(const OutputWindowScope&) = delete;
  OutputWindowScope& operator=(const OutputWindowScope&) = delete;
  const std::string& first() const { return m_window->first(); }

 private:
  vtkSmartPointer<vtkOutputWindow> m_previous;
  vtkLogger::Verbosity m_verbosity;
  vtkNew<CapturingOutputWindow> m_window;
};

/// Runs `reader` on `path` with every VTK message captured; the first becomes the message.
template <class Reader>
std::string runCaptured(Reader& reader, const std::filesystem::path& path) {
  std::string message;
  vtkNew<vtkCallbackCommand> observer;
  observer->SetCallback(collectMessage);
  observer->SetClientData(&message);
  const unsigned long onError = reader.AddObserver(vtkCommand::ErrorEvent, observer);
  const unsigned long onWarning = reader.AddObserver(vtkCommand::WarningEvent, observer);
  OutputWindowScope window;
  reader.SetFileName(path.c_str());
  reader.Update();
  // The reader outlives this frame (its caller reads the output): an event after the return
  // must not reach `message`, a dead local (its std::string writes happen in libstdc++, which
  // no sanitizer sees).
  reader.RemoveObserver(onError);
  reader.RemoveObserver(onWarning);
  observer->SetClientData(nullptr);
  return message.empty() ? window.first() : message;
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
  const std::string message = runCaptured(reader, path);
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

Result<VtkSurface> readVtkPolyData(const std::filesystem::path& path, bool xml) {
  vtkSmartPointer<vtkPolyData> poly;  // keeps the output alive after its reader
  std::string message;
  if (xml) {
    vtkNew<vtkXMLPolyDataReader> reader;
    message = runCaptured(*reader, path);
    poly = reader->GetOutput();
  } else {
    vtkNew<vtkPolyDataReader> reader;
    message = runCaptured(*reader, path);
    poly = reader->GetOutput();
  }
  if (!message.empty() || !poly)
    return Error{path.string() + ": VTK could not read it as " +
                 (xml ? "VTK XML PolyData" : "a legacy VTK surface (DATASET POLYDATA)") + ": " +
                 (message.empty() ? std::string("no output") : message) + "; check the file"};
  VtkSurface out;
  if (vtkPoints* points = poly->GetPoints()) {
    out.points.resize(std::size_t(points->GetNumberOfPoints()));
    for (vtkIdType p = 0; p < points->GetNumberOfPoints(); ++p)
      points->GetPoint(p, out.points[std::size_t(p)].data());
  }
  const auto copyCells = [](vtkCellArray* cells, std::vector<std::vector<std::int64_t>>& to) {
    if (!cells) return;
    vtkNew<vtkIdList> ids;
    for (cells->InitTraversal(); cells->GetNextCell(ids);) {
      std::vector<std::int64_t> cell(std::size_t(ids->GetNumberOfIds()));
      for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
        cell[std::size_t(k)] = ids->GetId(k);
      to.push_back(std::move(cell));
    }
  };
  copyCells(poly->GetPolys(), out.polygons);
  copyCells(poly->GetStrips(), out.strips);
  out.ignoredCells = std::size_t(poly->GetNumberOfVerts() + poly->GetNumberOfLines());
  return out;
}

}  // namespace tissue::volume::detail
