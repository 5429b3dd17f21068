#pragma once
/// \file
/// A scenario's static equilibrium (tissue-sim static): its springs, gravity and pins (its
/// instrument and dynamics keys are not used) solved to a force tolerance by regularised Newton
/// steps (sim/static_solve.h), with the positions in the mesh file's vertex order.

#include <string>

#include "tissue/core/result.h"
#include "tissue/scenario/scenario.h"
#include "tissue/sim/static_solve.h"

namespace tissue::studies {

/// What the solve found.
struct StaticSolution {
  sim::StaticSolveReport report;  ///< converged, iterations, accepted steps, residual (N)
  std::size_t vertices = 0;       ///< the surface's vertices (a lattice scenario's, by its embedding)
  double ms = 0.0;                ///< ms, wall time of the solve
  /// One "x y z" line (mm, 9 significant digits) per surface vertex, in the mesh file's order.
  std::string positionLines;
  /// {vertices, converged, iterations, accepted_steps, residual_N, tolerance_N, ms} as JSON text.
  std::string json;
};

/// Solves `scenario` (loaded, scenario::loadScenario) with `config`. A solve that does not reach
/// the tolerance is a solution with report.converged false (the caller says what to change).
Result<StaticSolution> solveScenarioStatic(const scenario::Scenario& scenario,
                                           const sim::StaticSolveConfig& config);

}  // namespace tissue::studies
