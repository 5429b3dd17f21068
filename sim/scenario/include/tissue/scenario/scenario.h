#pragma once
/// \file
/// Scenario files: one JSON object describing a simulation (mesh, springs, masses, damping,
/// gravity, pins, integrator, frames, instrument), parsed into a plain struct and built into a
/// mass-spring system. The schema, with units, is docs/SCENARIOS.md. Every error names the file
/// and the key ("liver.json: springs.stiffness: expected a positive number (N/mm), got -3");
/// unknown keys are errors too, so typos are caught.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "tissue/core/result.h"
#include "tissue/core/surface_mesh.h"
#include "tissue/sim/elastic_springs.h"
#include "tissue/sim/instrument.h"
#include "tissue/sim/integrators.h"
#include "tissue/sim/lattice.h"
#include "tissue/sim/mass.h"
#include "tissue/sim/simulator.h"
#include "tissue/sim/spring_network.h"
#include "tissue/sim/system.h"

namespace tissue::scenario {

/// Where the springs come from (springs.from).
enum class SpringSource {
  Surface,   ///< "surface": edge (and bending) springs of the surface mesh
  TetEdges,  ///< "tet-edges": one spring per edge of a tetrahedral mesh (mesh is .vtk/.vtu/.msh)
  Lattice,   ///< "lattice": a regular lattice embedding the surface (lattice.cell_size mm)
};

/// Pins given by region instead of indices: every vertex whose coordinate along `axis` is at
/// most `belowMm` (mm).
struct PinRegion {
  int axis = 2;          ///< 0 = x, 1 = y, 2 = z
  double belowMm = 0.0;  ///< mm
};

/// A scripted grasp or release at a time.
struct InstrumentAction {
  double time = 0.0;  ///< s: applied before the first frame starting at or after it
  bool grasp = true;  ///< true: grasp, false: release
};

/// The instrument of a scenario.
struct InstrumentSpec {
  sim::InstrumentConfig config{};
  std::vector<sim::ToolKeyframe> path;    ///< s -> mm
  std::vector<InstrumentAction> actions;  ///< sorted by time
};

/// The "tissue" block: spring stiffness from material constants instead of springs.stiffness
/// (tissue/sim/elastic_springs.h; docs/SCENARIOS.md).
struct TissueSpec {
  sim::ElasticMaterial material{};  ///< E in kPa, nu (validated, reported; the springs realise 1/4), g/mm^3
  sim::ShellConfig shell{};         ///< thickness (mm) and bending fraction, springs.from = "surface" only
};

/// A parsed scenario (all units as in docs/SCENARIOS.md; springs in N/mm or N, as SpringConfig).
struct Scenario {
  std::filesystem::path file;  ///< the scenario file (for messages)
  std::filesystem::path mesh;  ///< resolved mesh path
  double meshScaleToMm = 1.0;  ///< mm per mesh file unit
  SpringSource springSource = SpringSource::Surface;
  sim::SpringConfig springs{};     ///< stiffness N/mm (constant) or N (per-rest-length), damping N*s/mm
  double latticeCellSizeMm = 0.0;  ///< springs.from = "lattice" only
  sim::MassConfig mass{};          ///< g, or g/mm^2 (surface) / g/mm^3 (volume) density
  double massVolumeDensity = 0.0;  ///< g/mm^3 when given for a volume source
  sim::SystemConfig system{};      ///< gravity mm/s^2, Rayleigh alpha 1/s and beta s
  std::vector<std::uint32_t> pinnedIndices;  ///< file vertex indices (0-based)
  std::optional<PinRegion> pinnedRegion;
  sim::Integrator integrator = sim::Integrator::ImplicitEuler;
  double frameTime = 1.0 / 60.0;  ///< s (the key "dt")
  int substeps = 1;
  int frames = 60;
  sim::ImplicitSolverConfig solver{};
  std::optional<InstrumentSpec> instrument;
  /// How a diverged frame is handled (not a file key: studies switch the degrade off to see
  /// where an integrator fails).
  sim::RecoveryConfig recovery{};
  /// Set by the "tissue" block: springs from E (springs.stiffness is then not given).
  std::optional<TissueSpec> tissue;
  /// Lines to show the user (the commands print each on stderr), e.g. a Poisson's ratio that
  /// the springs cannot realise. Each names the file and the key.
  std::vector<std::string> warnings;
};

/// Where relative mesh paths may live besides the scenario's folder.
struct ScenarioPaths {
  std::filesystem::path sharedMeshesDir;  ///< e.g. ../shared/meshes; empty: none
};

/// Parses `text` as the scenario file `file` (used for messages and to resolve the mesh path).
Result<Scenario> parseScenario(const std::string& text, const std::filesystem::path& file,
                               const ScenarioPaths& paths = {});
/// Reads and parses the scenario file `file`.
Result<Scenario> loadScenario(const std::filesystem::path& file, const ScenarioPaths& paths = {});

/// The simulated mesh: surface positions and triangles over geometric vertices.
struct ScenarioMesh {
  SurfaceMesh surface;                   ///< as loaded (render vertices split at UV seams)
  std::vector<Float3> positions;         ///< mm, one per geometric (simulated) vertex
  std::vector<Triangle> triangles;       ///< over the geometric vertices
  std::vector<std::uint32_t> fileIndex;  ///< per geometric vertex: its 0-based index in the file
  /// springs.from = "tet-edges": the tets over `positions` (every vertex of the volume mesh;
  /// `triangles` are then its boundary faces, for contact and inspection).
  std::vector<Tet> tets;
  /// springs.from = "lattice": the lattice that carries the surface; the simulator moves its
  /// nodes and the surface follows by the embedding weights.
  std::optional<sim::EmbeddedLattice> lattice;

  /// The rest positions of the simulated vertices: the lattice nodes, or `positions`.
  std::vector<Float3> simulatedRestPositions() const;
};

/// Loads a tetrahedral mesh (.vtk, .vtu, .msh) for springs.from = "tet-edges".
Result<ScenarioMesh> loadTetScenarioMesh(const Scenario& scenario);
/// The volume mass settings of a scenario: mass.total (g) or mass.density (g/mm^3; liver's
/// 1.06e-3 when neither is given) and mass.distribution.
sim::VolumeMassConfig volumeMassConfig(const Scenario& scenario);
/// Fills `mesh` (a closed surface) with the lattice of springs.from = "lattice".
Result<void> attachLattice(const Scenario& scenario, ScenarioMesh& mesh);

/// Loads the scenario's mesh (relative to nothing: scenario.mesh is already resolved).
Result<ScenarioMesh> loadScenarioMesh(const Scenario& scenario);

/// The springs of the scenario's source: over the mesh's geometric vertices ("surface"), the
/// volume mesh's vertices ("tet-edges") or the lattice nodes ("lattice").
Result<sim::SpringNetwork> buildSpringsFromScenario(const Scenario& scenario, const ScenarioMesh& mesh);

/// Springs, masses, pins and global forces: the whole system. Errors name the scenario file
/// and the key.
Result<sim::MassSpringSystem> buildSystem(const Scenario& scenario, const ScenarioMesh& mesh);

}  // namespace tissue::scenario
