// tissue-sim sim-bench, the default scenario: data/scenarios/liver_poke_grasp.json (or another)
// run frame by frame as `simulate` runs it, contact and grasp included: ms per frame (median,
// p99, max), the cost of one substep, the force samples' rate, divergence events, refactoring.
#include <algorithm>
#include <cmath>

#include "sim_bench.h"
#include "tissue/core/statistics.h"
#include "tissue/scenario/scenario_run.h"
#include "tissue/studies/sim_bench.h"

namespace tissue::sim_app {
namespace {

nlohmann::json distribution(const std::vector<double>& values) {
  return {{"median", quantile(values, 0.5)}, {"p99", quantile(values, 0.99)}, {"max", quantile(values, 1.0)}};
}

}  // namespace

Result<nlohmann::json> measureScenario(const ScenarioBenchOptions& o) {
  auto parsed = scenario::loadScenario(o.scenario, {.sharedMeshesDir = o.sharedMeshesDir});
  if (!parsed) return parsed.error();
  if (o.frames > 0) parsed->frames = o.frames;
  if (o.integrator) parsed->integrator = *o.integrator;
  auto run = scenario::ScenarioRun::create(*parsed);
  if (!run) return run.error();
  std::vector<double> total, perSubstep, graspFrames;
  long samples = 0, events = 0, degraded = 0;
  double maxForce = 0.0, maxFactor = 0.0, simulated = 0.0;
  for (int f = 0; f < parsed->frames; ++f) {
    auto m = (*run)->advance();
    if (!m) return m.error();
    if (!m->finite) return Error{o.scenario.string() + ": frame " + std::to_string(f) + " holds NaN"};
    total.push_back(m->totalMs);
    perSubstep.push_back(m->totalMs / std::max(1, m->substeps));
    if (m->factorMs > 0.0 && m->grasped > 0) graspFrames.push_back(m->totalMs);
    samples += static_cast<long>(m->forceSamplesN.size());
    events += m->divergenceEvents;
    degraded += m->degrade.empty() ? 0 : 1;
    maxForce = std::max(maxForce, m->forceMagnitudeN);
    maxFactor = std::max(maxFactor, m->factorMs);
    simulated += parsed->frameTime;
  }
  const auto& system = (*run)->simulator().system();
  nlohmann::json out;
  out["scenario"] = o.scenario.string();
  out["integrator"] = sim::integratorName(parsed->integrator);
  out["substeps"] = parsed->substeps;
  out["frames"] = parsed->frames;
  out["simulated_vertices"] = system.vertexCount();
  out["springs"] = system.springs.size();
  out["surface_vertices"] = (*run)->mesh().positions.size();
  out["frame_ms"] = distribution(total);
  out["substep_ms"] = distribution(perSubstep);
  out["force_update_hz"] = simulated > 0.0 ? double(samples) / simulated : 0.0;
  out["divergence_events"] = events;
  out["degraded_frames"] = degraded;
  out["max_force_N"] = maxForce;
  out["max_factor_ms"] = maxFactor;
  if (!graspFrames.empty()) out["refactor_frame_ms_max"] = quantile(graspFrames, 1.0);
  out["explicit_limit_ms"] = 2.0e3 / studies::omegaBound(system);  // 2 / omega_max (Gershgorin), ms
  return out;
}

}  // namespace tissue::sim_app
