// Scenario -> mesh, springs, masses, pins: the mass-spring system.
#include <string>
#include <unordered_map>

#include "tissue/mesh/load_mesh.h"
#include "tissue/scenario/scenario.h"
#include "tissue/sim/elastic_springs.h"
#include "tissue/sim/tet_springs.h"

namespace tissue::scenario {
namespace {

Error keyError(const Scenario& s, const std::string& key, const std::string& what) {
  return Error{s.file.string() + ": " + key + ": " + what};
}

/// The pinned vertices (geometric indices) from the list of file indices or the region.
Result<std::vector<std::uint32_t>> pinnedVertices(const Scenario& s, const ScenarioMesh& mesh) {
  std::vector<std::uint32_t> out;
  if (s.pinnedRegion) {
    for (std::uint32_t v = 0; v < mesh.positions.size(); ++v) {
      const Float3& p = mesh.positions[v];
      const double c = s.pinnedRegion->axis == 0 ? p.x : s.pinnedRegion->axis == 1 ? p.y : p.z;
      if (c <= s.pinnedRegion->belowMm) out.push_back(v);
    }
    if (out.empty())
      return keyError(s, "pinned.below", "pins no vertex; raise it above the mesh's lowest point");
    return out;
  }
  std::unordered_map<std::uint32_t, std::uint32_t> geometricOf;
  for (std::uint32_t v = 0; v < mesh.fileIndex.size(); ++v)
    geometricOf.emplace(mesh.fileIndex[v], v);
  for (std::size_t k = 0; k < s.pinnedIndices.size(); ++k) {
    const auto it = geometricOf.find(s.pinnedIndices[k]);
    if (it == geometricOf.end())
      return keyError(s, "pinned[" + std::to_string(k) + "]",
                      "vertex " + std::to_string(s.pinnedIndices[k]) + " is not a vertex of a face of " +
                          s.mesh.string() + " (" + std::to_string(mesh.positions.size()) + " used vertices)");
    out.push_back(it->second);
  }
  return out;
}

std::vector<sim::Vec3d> restPositions(const std::vector<Float3>& positions) {
  std::vector<sim::Vec3d> out;
  out.reserve(positions.size());
  for (const Float3& p : positions)
    out.push_back({p.x, p.y, p.z});
  return out;
}

}  // namespace

Result<ScenarioMesh> loadScenarioMesh(const Scenario& s) {
  const std::string ext = s.mesh.extension().string();
  if (s.springSource == SpringSource::TetEdges) return loadTetScenarioMesh(s);
  if (ext == ".vtk" || ext == ".vtu" || ext == ".msh")
    return keyError(s, "mesh",
                    "a tetrahedral mesh (" + ext +
                        ") needs springs.from = \"tet-edges\"; for \"surface\" or "
                        "\"lattice\" give a surface mesh (.obj, .ply, .off, .stl)");
  auto loaded = mesh::loadMesh(s.mesh, {.scaleToMm = static_cast<float>(s.meshScaleToMm)});
  if (!loaded) return keyError(s, "mesh", loaded.error().message);
  ScenarioMesh m;
  m.surface = std::move(*loaded);
  m.positions.resize(m.surface.geometricVertexCount);
  for (std::size_t r = 0; r < m.surface.positions.size(); ++r)
    m.positions[m.surface.geometricIndex[r]] = m.surface.positions[r];
  m.triangles.reserve(m.surface.triangles.size());
  for (const Triangle& t : m.surface.triangles)
    m.triangles.push_back(
        {m.surface.geometricIndex[t[0]], m.surface.geometricIndex[t[1]], m.surface.geometricIndex[t[2]]});
  m.fileIndex = m.surface.geometricSourceIndex;
  if (m.fileIndex.size() != m.positions.size()) {  // a loader without the map: first-use order
    m.fileIndex.resize(m.positions.size());
    for (std::uint32_t v = 0; v < m.fileIndex.size(); ++v)
      m.fileIndex[v] = v;
  }
  if (s.springSource == SpringSource::Lattice)
    if (auto attached = attachLattice(s, m); !attached) return attached.error();
  return m;
}

Result<sim::SpringNetwork> buildSpringsFromScenario(const Scenario& s, const ScenarioMesh& mesh) {
  switch (s.springSource) {
    case SpringSource::Surface: {
      sim::SpringConfig config = s.springs;
      // With a tissue block the builder makes the springs and elastic_springs sets their k.
      if (s.tissue) config.bendingStiffness = s.tissue->shell.bendingFraction > 0.0 ? 1.0 : 0.0;
      auto springs = sim::buildSurfaceSprings(mesh.positions, mesh.triangles, config);
      if (!springs) return keyError(s, "springs", springs.error().message);
      if (s.tissue)
        if (auto ok = sim::setSurfaceStiffness(*springs, restPositions(mesh.positions), mesh.triangles,
                                               s.tissue->material, s.tissue->shell);
            !ok)
          return keyError(s, "tissue", ok.error().message);
      return springs;
    }
    case SpringSource::TetEdges: {
      auto springs = sim::buildTetEdgeSprings(mesh.positions, mesh.tets, s.springs);
      if (!springs) return keyError(s, "springs", springs.error().message);
      if (s.tissue)
        if (auto ok = sim::setTetEdgeStiffness(*springs, restPositions(mesh.positions), mesh.tets,
                                               s.tissue->material);
            !ok)
          return keyError(s, "tissue", ok.error().message);
      return springs;
    }
    case SpringSource::Lattice:
      if (!mesh.lattice) return keyError(s, "springs.from", "\"lattice\": the mesh carries no lattice");
      return mesh.lattice->springs;
  }
  return keyError(s, "springs.from", "unknown source");
}

Result<sim::MassSpringSystem> buildSystem(const Scenario& s, const ScenarioMesh& mesh) {
  auto springs = buildSpringsFromScenario(s, mesh);
  if (!springs) return springs.error();
  auto masses = s.springSource == SpringSource::TetEdges
                    ? sim::computeTetMasses(mesh.positions, mesh.tets, volumeMassConfig(s))
                : mesh.lattice ? Result<std::vector<double>>(mesh.lattice->masses)
                               : sim::computeMasses(mesh.positions, mesh.triangles, s.mass);
  if (!masses) return keyError(s, "mass", masses.error().message);
  auto pinned = pinnedVertices(s, mesh);
  if (!pinned) return pinned.error();
  // A pinned surface vertex of a lattice is held by pinning every corner of its cell.
  if (mesh.lattice) *pinned = sim::cellNodes(*mesh.lattice, *pinned);
  auto system = sim::makeSystem(std::move(*springs), std::move(*masses), *pinned, s.system);
  if (!system) return keyError(s, "pinned", system.error().message);
  return system;
}

}  // namespace tissue::scenario
