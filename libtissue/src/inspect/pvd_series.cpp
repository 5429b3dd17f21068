// The ParaView time series: one VTK XML file per frame and the .pvd collection, all atomic.
#include "tissue/inspect/pvd_series.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkUnstructuredGrid.h>

#include <cstdio>

#include "tissue/core/atomic_file.h"
#include "tissue/core/stopwatch.h"
#include "vtk_io.h"

namespace tissue::inspect {
namespace {

/// Point data of a frame over its points (the nodes and/or the surface's vertices).
struct PointArrays {
  std::vector<Float3> velocity, contactForce, planeNormal, normal;
  std::vector<float> stretch, strain, planeOffset, planeResidual;
  std::vector<Float4> tangent;

  /// Appends the surface's vertices (with `velocity` and `stretch` of their own).
  void addSurface(const SurfaceState& s) {
    velocity.insert(velocity.end(), s.velocities.begin(), s.velocities.end());
    stretch.insert(stretch.end(), s.stretch.begin(), s.stretch.end());
    contactForce.insert(contactForce.end(), s.contactForceN.begin(), s.contactForceN.end());
    planeNormal.insert(planeNormal.end(), s.planeNormals.begin(), s.planeNormals.end());
    normal.insert(normal.end(), s.normals.begin(), s.normals.end());
    planeOffset.insert(planeOffset.end(), s.planeOffsetMm.begin(), s.planeOffsetMm.end());
    planeResidual.insert(planeResidual.end(), s.planeResidualMm.begin(), s.planeResidualMm.end());
    tangent.insert(tangent.end(), s.tangents.begin(), s.tangents.end());
  }
  /// Appends a lattice's nodes: their motion and stretch, no surface fields (0), no contact
  /// force (it is on the surface's vertices, which the tool touches).
  void addNodes(const NodeState& n) {
    const std::size_t count = n.positions.size();
    velocity.insert(velocity.end(), n.velocities.begin(), n.velocities.end());
    stretch.insert(stretch.end(), n.stretch.begin(), n.stretch.end());
    contactForce.resize(contactForce.size() + count);
    planeNormal.resize(planeNormal.size() + count);
    normal.resize(normal.size() + count);
    planeOffset.resize(planeOffset.size() + count, 0.0f);
    planeResidual.resize(planeResidual.size() + count, 0.0f);
    tangent.resize(tangent.size() + count);
  }
  void addTo(vtkPointData* data) {
    strain.resize(stretch.size());
    for (std::size_t i = 0; i < stretch.size(); ++i)
      strain[i] = stretch[i] - 1.0f;
    addArray(data, "velocity_mm_per_s", velocity);
    addArray(data, "stretch", stretch);
    addArray(data, "strain", strain);
    addArray(data, "contact_force_N", contactForce);
    addArray(data, "plane_normal", planeNormal);
    addArray(data, "plane_offset_mm", planeOffset);
    addArray(data, "plane_residual_mm", planeResidual);
    addArray(data, "tangent", tangent);
    addArray(data, "normal", normal);
  }
};

float meanOf(std::span<const float> values, std::span<const std::uint32_t> ids, std::uint32_t offset) {
  float sum = 0.0f;
  for (std::uint32_t id : ids)
    sum += values[id + offset];
  return ids.empty() ? 0.0f : sum / float(ids.size());
}

vtkSmartPointer<vtkPolyData> surfaceFrame(const OrganSnapshot& f) {
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(pointsOf(f.surface.positions));
  vtkNew<vtkCellArray> cells;
  for (const Triangle& t : f.surface.triangles) {
    const vtkIdType ids[3] = {vtkIdType(t[0]), vtkIdType(t[1]), vtkIdType(t[2])};
    cells->InsertNextCell(3, ids);
  }
  poly->SetPolys(cells);
  PointArrays arrays;
  arrays.addSurface(f.surface);
  arrays.addTo(poly->GetPointData());
  std::vector<float> cellStrain, surface(f.surface.triangles.size(), 1.0f);
  for (const Triangle& t : f.surface.triangles)
    cellStrain.push_back(meanOf(arrays.strain, t, 0));
  addArray(poly->GetCellData(), "strain", cellStrain);
  addArray(poly->GetCellData(), "surface", surface);
  return poly;
}

vtkSmartPointer<vtkUnstructuredGrid> volumeFrame(const OrganSnapshot& f) {
  // Points: the nodes, then (lattice) the surface's vertices; a tet mesh's surface is its nodes.
  const bool lattice = !f.nodes.hexes.empty();
  std::vector<Float3> positions = f.nodes.positions;
  PointArrays arrays;
  std::uint32_t surfaceOffset = 0;
  if (lattice) {
    positions.insert(positions.end(), f.surface.positions.begin(), f.surface.positions.end());
    surfaceOffset = std::uint32_t(f.nodes.positions.size());
    arrays.addNodes(f.nodes);
    arrays.addSurface(f.surface);
  } else {
    SurfaceState s = f.surface;
    s.velocities = f.nodes.velocities;
    s.stretch = f.nodes.stretch;
    s.contactForceN = f.nodes.contactForceN;
    arrays.addSurface(s);
  }
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  grid->SetPoints(pointsOf(positions));
  arrays.addTo(grid->GetPointData());
  std::vector<float> cellStrain, surface;
  const auto add = [&](int type, std::span<const std::uint32_t> ids, std::uint32_t offset, float isSurface) {
    vtkIdType cell[8];
    for (std::size_t k = 0; k < ids.size(); ++k)
      cell[k] = vtkIdType(ids[k] + offset);
    grid->InsertNextCell(type, vtkIdType(ids.size()), cell);
    cellStrain.push_back(meanOf(arrays.strain, ids, offset));
    surface.push_back(isSurface);
  };
  grid->Allocate(vtkIdType(f.nodes.tets.size() + f.nodes.hexes.size() + f.surface.triangles.size()));
  for (const Tet& t : f.nodes.tets)
    add(VTK_TETRA, t, 0, 0.0f);
  for (const auto& h : f.nodes.hexes)
    add(VTK_HEXAHEDRON, h, 0, 0.0f);
  for (const Triangle& t : f.surface.triangles)
    add(VTK_TRIANGLE, t, surfaceOffset, 1.0f);
  addArray(grid->GetCellData(), "strain", cellStrain);
  addArray(grid->GetCellData(), "surface", surface);
  return grid;
}

bool isVolume(const OrganSnapshot& f) {
  return !f.nodes.tets.empty() || !f.nodes.hexes.empty();
}

Result<void> checkFrame(const OrganSnapshot& f) {
  const std::size_t g = f.surface.positions.size();
  const bool surfaceOk = f.surface.velocities.size() == g && f.surface.stretch.size() == g &&
                         f.surface.contactForceN.size() == g && f.surface.planeNormals.size() == g &&
                         f.surface.planeOffsetMm.size() == g && f.surface.planeResidualMm.size() == g &&
                         f.surface.tangents.size() == g && f.surface.normals.size() == g;
  const std::size_t n = f.nodes.positions.size();
  const bool nodesOk = f.nodes.velocities.size() == n && f.nodes.stretch.size() == n &&
                       f.nodes.contactForceN.size() == n && (!f.nodes.tets.size() || n == g);
  if (!surfaceOk || !nodesOk)
    return Error{"ParaView frame " + std::to_string(f.frame) +
                 ": the snapshot's arrays do not match its meshes; take it with inspect::snapshotOf"};
  return {};
}

std::string pvdText(const std::string& entries) {
  return "<?xml version=\"1.0\"?>\n"
         "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
         "  <Collection>\n" +
         entries +
         "  </Collection>\n"
         "</VTKFile>\n";
}

}  // namespace

Result<std::filesystem::path> writeOrganFrame(const OrganSnapshot& frame, const std::filesystem::path& path) {
  if (auto ok = checkFrame(frame); !ok) return ok.error();
  auto target = path;
  if (isVolume(frame)) {
    target.replace_extension(".vtu");
    if (auto w = writeXmlAtomic(volumeFrame(frame), target); !w) return w.error();
  } else {
    target.replace_extension(".vtp");
    if (auto w = writeXmlAtomic(surfaceFrame(frame), target); !w) return w.error();
  }
  return target;
}

PvdSeries::PvdSeries(std::filesystem::path dir, std::string name)
    : m_dir(std::move(dir)), m_name(std::move(name)), m_pvd(m_dir / (m_name + ".pvd")) {}

Result<PvdSeries> PvdSeries::create(const std::filesystem::path& dir, const std::string& name) {
  if (name.empty() || name.find('/') != std::string::npos)
    return Error{"ParaView series: name '" + name + "' must be a plain file stem (no '/'), e.g. \"organ\""};
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir))
    return Error{"ParaView series: cannot create the folder '" + dir.string() +
                 "'; check the path and permissions"};
  return PvdSeries(dir, name);
}

Result<PvdFrameCost> PvdSeries::addFrame(const OrganSnapshot& frame) {
  if (!m_entries.empty() && !(frame.timeS > m_entries.back().timeS))
    return Error{"ParaView series " + m_pvd.string() + ": frame " + std::to_string(frame.frame) +
                 " at t = " + std::to_string(frame.timeS) + " s does not follow the last time step (" +
                 std::to_string(m_entries.back().timeS) + " s); add frames in time order"};
  PvdFrameCost cost;
  Stopwatch build;
  char stem[64];
  std::snprintf(stem, sizeof stem, "_%06zu", m_entries.size());
  auto written = writeOrganFrame(frame, m_dir / (m_name + stem));
  if (!written) return written.error();
  cost.frameMs = build.elapsedMs();
  Stopwatch write;
  m_entries.push_back({frame.timeS, written->filename().string()});
  std::string entries;
  for (const Entry& e : m_entries) {
    char line[512];
    std::snprintf(line, sizeof line, "    <DataSet timestep=\"%.17g\" group=\"\" part=\"0\" file=\"%s\"/>\n",
                  e.timeS, e.file.c_str());
    entries += line;
  }
  if (auto w = writeTextFileAtomic(m_pvd, pvdText(entries)); !w) {
    m_entries.pop_back();
    return w.error();
  }
  cost.collectionMs = write.elapsedMs();
  return cost;
}

std::vector<std::filesystem::path> PvdSeries::framePaths() const {
  std::vector<std::filesystem::path> paths;
  for (const Entry& e : m_entries)
    paths.push_back(m_dir / e.file);
  return paths;
}

}  // namespace tissue::inspect
