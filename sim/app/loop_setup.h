#pragma once
/// \file
/// What `demo` and `replay` share around the library's loop (tissue::scene::OrganLoop): the
/// organ a scenario moves (the scene module's assets: mesh with UVs, material, textures, plane
/// settings), and the per-phase
/// figures of a run (median, p99, max ms) for the reports.

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "organ_data.h"
#include "tissue/core/result.h"
#include "tissue/scenario/scenario.h"
#include "tissue/scene/organ_loop.h"

namespace tissue::sim_app {

/// A scenario and the organ it moves, ready for scene::OrganLoop::create.
struct LoopOrgan {
  scenario::Scenario scenario;
  /// The scenario's mesh (or the override) with UVs (mm), data/materials/<mesh stem>.json, its
  /// textures, and planes sized by the outer layer's extinction (François eq. 8).
  scene::OrganAssets assets;
};

/// Loads `scenarioFile` (shared meshes from ../shared/meshes) and its organ (scene::loadOrganAssets
/// of its mesh, or `meshOverride`, and data/materials/<mesh stem>.json).
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
