// The two volumetric spring sources of a scenario: a tetrahedral mesh ("tet-edges") and a closed
// surface embedded in a coarse lattice ("lattice"), see docs/SCENARIOS.md.
#include <string>

#include "tissue/scenario/scenario.h"
#include "tissue/sim/elastic_springs.h"
#include "tissue/volume/tet_mesh.h"

namespace tissue::scenario {
namespace {

Error keyError(const Scenario& s, const std::string& key, const std::string& what) {
  return Error{s.file.string() + ": " + key + ": " + what};
}

}  // namespace

std::vector<Float3> ScenarioMesh::simulatedRestPositions() const {
  if (!lattice) return positions;
  return sim::toFloat3(lattice->nodePositions);
}

Result<ScenarioMesh> loadTetScenarioMesh(const Scenario& s) {
  if (!volume::isTetMeshPath(s.mesh))
    return keyError(
        s, "mesh",
        "springs.from = \"tet-edges\" needs a tetrahedral mesh (.vtk, .vtu or .msh), got " + s.mesh.string());
  auto tets = volume::loadTetMesh(s.mesh, {.scaleToMm = static_cast<float>(s.meshScaleToMm)});
  if (!tets) return keyError(s, "mesh", tets.error().message);
  ScenarioMesh m;
  m.positions = std::move(tets->positions);
  m.tets = std::move(tets->tets);
  m.triangles = volume::boundaryTriangles({m.positions, m.tets});
  // The surface seen by the renderer and the inspection: every vertex, the boundary faces.
  m.surface.positions = m.positions;
  m.surface.triangles = m.triangles;
  m.surface.geometricVertexCount = static_cast<std::uint32_t>(m.positions.size());
  m.surface.geometricIndex.resize(m.positions.size());
  m.fileIndex.resize(m.positions.size());
  for (std::uint32_t v = 0; v < m.positions.size(); ++v)
    m.surface.geometricIndex[v] = m.fileIndex[v] = v;
  m.surface.geometricSourceIndex = m.fileIndex;
  return m;
}

Result<void> attachLattice(const Scenario& s, ScenarioMesh& mesh) {
  sim::LatticeConfig config;
  config.cellSize = s.latticeCellSizeMm;
  config.springs = s.springs;
  config.mass = volumeMassConfig(s);
  auto lattice = sim::buildEmbeddedLattice(mesh.positions, mesh.triangles, config);
  if (!lattice) return keyError(s, "springs.from", "\"lattice\": " + lattice.error().message);
  if (s.tissue)  // springs from E: assembled cell by cell (tissue/sim/elastic_springs.h)
    if (auto ok = sim::setLatticeStiffness(*lattice, s.tissue->material); !ok)
      return keyError(s, "tissue", ok.error().message);
  mesh.lattice = std::move(*lattice);
  return {};
}

sim::VolumeMassConfig volumeMassConfig(const Scenario& s) {
  sim::VolumeMassConfig config;
  config.total = s.mass.total;
  if (s.massVolumeDensity > 0.0) config.density = s.massVolumeDensity;
  config.distribution = s.mass.distribution;
  return config;
}

}  // namespace tissue::scenario
