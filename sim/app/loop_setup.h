#pragma once
/// \file
/// What `demo` and `replay` share around the library's loop (tissue::scene::OrganLoop): the
/// organ a scenario moves (its mesh with UVs, material and plane settings), and the per-phase
/// figures of a run (median, p99, max ms) for the reports.

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "material_file.h"
#include "tissue/core/result.h"
#include "tissue/core/surface_mesh.h"
#include "tissue/mesh/local_planes.h"
#include "tissue/scenario/scenario.h"
#include "tissue/scene/organ_loop.h"

namespace tissue::sim_app {

/// A scenario and the organ it moves, ready for scene::OrganLoop::create.
struct LoopOrgan {
  scenario::Scenario scenario;
  SurfaceMesh mesh;  ///< the scenario's mesh (or the override), with UVs, mm
  LayeredMaterial material;
  mesh::PlaneFitSettings planes;  ///< radius from the outer layer's extinction (François eq. 8)
};

/// Loads `scenarioFile` (shared meshes from ../shared/meshes), its mesh (or `meshOverride`) with
/// UVs, and data/materials/<mesh stem>.json.
Result<LoopOrgan> loadLoopOrgan(const std::filesystem::path& scenarioFile,
                                const std::string& meshOverride = {});

/// Per-frame cost of each phase (ms), in the order the loop runs them.
struct PhaseSamples {
  std::vector<std::pair<std::string, std::vector<double>>> phases{
      {"1 simulate (springs, contact, grasp)", {}},
      {"2 mesh: positions in", {}},
      {"2 mesh: normals", {}},
      {"2 mesh: planes (incremental)", {}},
      {"2 mesh: tangent frames", {}},
      {"3 upload", {}},
      {"4 render (lit, read back)", {}},
      {"frame total", {}}};
  void add(const scene::LoopFrame& f);
};

/// Three significant digits: figures for people to read (CSV files keep every digit).
double rounded(double x);

/// [{phase, median_ms, p99_ms, max_ms}] with rounded figures.
nlohmann::json phaseReport(const PhaseSamples& samples);

}  // namespace tissue::sim_app
