// A scenario run's summary (scenario_summary.h).
#include "tissue/studies/scenario_summary.h"

#include <nlohmann/json.hpp>

#include "tissue/core/statistics.h"

namespace tissue::studies {

std::string scenarioRunSummaryJson(const scenario::ScenarioRun& run,
                                   const std::vector<scenario::FrameMetrics>& frames, double wallMs) {
  const scenario::RunSummary s = scenario::summarize(frames);
  std::vector<double> total;
  std::size_t samples = 0;
  for (const auto& f : frames) {
    total.push_back(f.totalMs);
    samples += f.forceSamplesN.size();
  }
  const double simulatedS =
      frames.empty() ? 0.0 : frames.back().timeS - frames.front().timeS + run.scenario().frameTime;
  const nlohmann::json j{
      {"scenario", run.scenario().file.string()},
      {"mesh", run.scenario().mesh.string()},
      {"vertices", run.mesh().positions.size()},
      {"simulated_vertices", run.simulator().system().vertexCount()},
      {"springs", run.simulator().system().springs.size()},
      {"substeps", run.simulator().substeps()},
      {"integrator", sim::integratorName(run.simulator().integrator())},
      {"frames", s.frames},
      {"nan_frames", s.nanFrames},
      {"divergence_events", s.divergenceEvents},
      {"degraded_frames", s.degradedFrames},
      {"frame_ms",
       {{"median", quantile(total, 0.5)}, {"p99", quantile(total, 0.99)}, {"max", quantile(total, 1.0)}}},
      {"max_factor_ms", s.maxFactorMs},
      {"force_update_hz", simulatedS > 0.0 ? double(samples) / simulatedS : 0.0},
      {"max_contact_force_N", s.maxForceN},
      {"mean_contact_force_N", s.meanForceN},
      {"ms_per_frame",
       {{"integrate", s.meanIntegrateMs},
        {"contact", s.meanContactMs},
        {"check", s.meanCheckMs},
        {"rollback", s.meanRollbackMs},
        {"actions", s.meanActionMs},
        {"total", s.meanTotalMs}}},
      // Each frame's work, counted (issue 14): the worst frame against the simulator's stated bound.
      {"max_frame_steps", s.maxFrameSteps},
      {"max_frame_solver_iterations", s.maxFrameSolverIterations},
      {"frame_work_bound",
       {{"steps", run.frameWorkBound().steps}, {"solver_iterations", run.frameWorkBound().solverIterations}}},
      {"tool_teleports", s.teleports},
      {"wall_ms", wallMs}};
  return j.dump();
}

}  // namespace tissue::studies
