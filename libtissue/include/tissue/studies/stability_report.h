#pragma once
/// \file
/// The one-spring stability study (tissue/sim/stability_study.h) as `tissue-sim stability`
/// reports it: a table of the largest stable time step of each integrator against the theory,
/// the JSON of every case with a summary, and the chart of max dt / 2 sqrt(m/k) against the
/// stiffness. Masses in g, stiffnesses in N/mm, time steps in s (JSON) and ms (table).

#include <string>
#include <vector>

#include "tissue/inspect/chart.h"
#include "tissue/sim/stability_study.h"
#include "tissue/studies/report.h"

namespace tissue::studies {

/// What the study found and how to report it.
struct StabilityReport {
  std::vector<sim::StabilityCase> cases;
  double studyMs = 0.0;  ///< ms, wall time of the study
  std::string markdown;  ///< the table, one row per case (time steps in ms)
  /// stability.json: "model", "units", "cases" (integrator, mass, stiffness, reference_dt,
  /// theory_max_dt, measured_max_dt, measured_over_theory, ..., verdict) and "summary".
  std::string json;
  Report report;  ///< stability.md, stability.json, stability_chart.csv, stability.png
};

/// "limit found", "stable up to the largest step tested" or "unstable at every step tested".
std::string stabilityVerdict(const sim::StabilityCase& c);

/// The table: one row per case; time steps in ms; measured / theory where both exist.
Table stabilityTable(const std::vector<sim::StabilityCase>& cases);

/// The chart's series: per integrator and mass, max dt / 2 sqrt(m/k) against the stiffness
/// (N/mm). A case stable up to the largest step tested is drawn at that bound (a lower bound on
/// its limit); explicit Euler, stable at no step, is left out.
std::vector<inspect::ChartSeries> stabilityChartSeries(const std::vector<sim::StabilityCase>& cases);

/// Runs the study and assembles its report.
StabilityReport runStabilityReport(const sim::StabilityStudyConfig& config);

}  // namespace tissue::studies
