#pragma once
/// \file
/// The stability study on the organ (tissue/scenario/organ_stability.h) as `tissue-sim
/// organ-stability` reports it: per integrator and Young's modulus the largest stable frame
/// step and the cost of a stable 1/60 s frame, as a Markdown table, JSON and two charts.
/// Moduli in kPa, steps in ms, costs in ms per frame.

#include <filesystem>
#include <string>
#include <vector>

#include "tissue/core/result.h"
#include "tissue/scenario/organ_stability.h"
#include "tissue/studies/report.h"

namespace tissue::studies {

struct OrganStabilityReport {
  std::vector<scenario::OrganStabilityRow> rows;
  /// organ_stability.json: scenario, window_s, min_step_ms, max_step_ms and "rows" (integrator,
  /// youngs_modulus_kpa, max_stable_step_ms, stable_at_max_tested, substeps_per_60hz_frame,
  /// ms_per_frame_median, ms_per_frame_max, trials).
  std::string json;
  /// organ_stability.md, organ_stability.json, and the charts that have data:
  /// organ_stability_limits.png (the conditionally stable integrators' limits) and
  /// organ_stability_cost.png (what a stable 60 Hz frame costs).
  Report report;
};

/// The table: one row per integrator and modulus.
Table organStabilityTable(const std::vector<scenario::OrganStabilityRow>& rows, double maxStepMs);

/// Loads `scenarioFile` (relative meshes under `paths`), runs the study and assembles the report.
Result<OrganStabilityReport> runOrganStabilityReport(const std::filesystem::path& scenarioFile,
                                                     const scenario::ScenarioPaths& paths,
                                                     const scenario::OrganStabilityConfig& config);

}  // namespace tissue::studies
