// A ParaView series of a bare scenario run: the run's surface kept in step here (pvd_series.h).
// Built with and without VTK (without it, PvdSeries::create is the Error).
#include <algorithm>

#include "tissue/core/vec_math.h"
#include "tissue/inspect/pvd_series.h"
#include "tissue/mesh/deformable_surface.h"
#include "tissue/scenario/scenario_run.h"

namespace tissue::inspect {
namespace {

/// `mesh` with UVs: its own, or the planar projection (x, y) over its bounding box.
SurfaceMesh withUvs(SurfaceMesh mesh) {
  if (mesh.hasUvs()) return mesh;
  const Bounds3 box = boundsOf(mesh.positions);
  const float sx = std::max(box.hi.x - box.lo.x, 1e-6f), sy = std::max(box.hi.y - box.lo.y, 1e-6f);
  mesh.uvs.clear();
  for (const Float3& p : mesh.positions)
    mesh.uvs.push_back({(p.x - box.lo.x) / sx, (p.y - box.lo.y) / sy});
  return mesh;
}

}  // namespace

RunSeries::RunSeries(PvdSeries series, std::unique_ptr<mesh::DeformableSurface> surface)
    : m_series(std::move(series)), m_surface(std::move(surface)) {}
RunSeries::~RunSeries() = default;
RunSeries::RunSeries(RunSeries&&) noexcept = default;
RunSeries& RunSeries::operator=(RunSeries&&) noexcept = default;

Result<RunSeries> RunSeries::create(const scenario::ScenarioRun& run, const std::filesystem::path& dir,
                                    const std::string& name) {
  auto series = PvdSeries::create(dir, name);
  if (!series) return series.error();
  auto surface = mesh::DeformableSurface::create(withUvs(run.mesh().surface));
  if (!surface)
    return Error{"ParaView series of " + run.scenario().file.string() + ": " + surface.error().message};
  return RunSeries(std::move(*series), std::make_unique<mesh::DeformableSurface>(std::move(*surface)));
}

Result<PvdFrameCost> RunSeries::addFrame(const scenario::ScenarioRun& run) {
  const std::vector<Float3> positions = run.positions();
  if (positions.size() != m_surface->geometricPositions().size())
    return Error{"ParaView series: the run has " + std::to_string(positions.size()) +
                 " surface vertices, the series " + std::to_string(m_surface->geometricPositions().size()) +
                 "; start a series per run"};
  m_surface->update(positions);
  return m_series.addFrame(snapshotOf(run, *m_surface));
}

}  // namespace tissue::inspect
