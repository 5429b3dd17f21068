#pragma once
/// \file
/// A scenario run's summary (tissue-sim simulate's summary.json): the organ, the simulator, the
/// frames' health, time and work, and the tool force, as a JSON object's text.

#include <string>
#include <vector>

#include "tissue/scenario/scenario_run.h"

namespace tissue::studies {

/// The summary of `frames` run by `run` in `wallMs` (ms): scenario, mesh, vertices,
/// simulated_vertices, springs, substeps, integrator; frames, nan_frames, divergence_events,
/// degraded_frames; frame_ms {median, p99, max} and ms_per_frame {integrate, contact, check,
/// rollback, actions, total} (ms); max_factor_ms; force_update_hz (force samples per simulated
/// second); max_ and mean_contact_force_N (N); each frame's work against the simulator's bound
/// (max_frame_steps, max_frame_solver_iterations, frame_work_bound {steps, solver_iterations},
/// issue 14); tool_teleports; wall_ms.
std::string scenarioRunSummaryJson(const scenario::ScenarioRun& run,
                                   const std::vector<scenario::FrameMetrics>& frames, double wallMs);

}  // namespace tissue::studies
