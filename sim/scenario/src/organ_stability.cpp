// The stability study on the organ: bisection of the largest stable frame step per integrator
// and modulus, then the substeps (and ms) each needs per 60 Hz frame.
#include "tissue/scenario/organ_stability.h"

#include <cmath>

#include "tissue/core/statistics.h"
#include "tissue/core/stopwatch.h"
#include "tissue/scenario/scenario_run.h"

namespace tissue::scenario {
namespace {

/// The scenario at one modulus and integrator, with the degrade off: a divergence is reported
/// and the frame relaxed, never rescued by another integrator or hidden by the budget.
Scenario variant(const Scenario& base, sim::Integrator integrator, double youngsModulusKpa) {
  Scenario s = base;
  s.integrator = integrator;
  s.tissue->material.youngsModulusKpa = youngsModulusKpa;
  s.recovery.switchIntegrator = false;
  s.recovery.frameBudgetMs = 0.0;
  return s;
}

/// Runs the window; `frameMs` (optional) receives each frame's wall time.
Result<bool> runWindow(const Scenario& scenario, double stepS, int substeps, double windowS,
                       std::vector<double>* frameMs) {
  Scenario s = scenario;
  s.frameTime = stepS * substeps;
  s.substeps = substeps;
  s.frames = static_cast<int>(std::ceil(windowS / s.frameTime));
  auto run = ScenarioRun::create(s);
  if (!run) return run.error();
  for (int f = 0; f < s.frames; ++f) {
    Stopwatch clock;
    auto m = (*run)->advance();
    if (!m) return m.error();
    if (frameMs) frameMs->push_back(clock.elapsedMs());
    if (m->divergenceEvents > 0 || !m->finite) return false;
  }
  return true;
}

}  // namespace

Result<bool> runsStably(const Scenario& scenario, double stepS, int substeps, double windowS) {
  return runWindow(scenario, stepS, substeps, windowS, nullptr);
}

Result<std::vector<OrganStabilityRow>> runOrganStabilityStudy(const Scenario& base,
                                                              const OrganStabilityConfig& config) {
  if (!base.tissue)
    return Error{base.file.string() +
                 ": the organ stability study varies Young's modulus; give the tissue as a \"tissue\" block "
                 "(youngs_modulus_kpa) instead of springs.stiffness"};
  std::vector<OrganStabilityRow> rows;
  for (double e : config.youngsModuliKpa)
    for (sim::Integrator integrator : config.integrators) {
      const Scenario s = variant(base, integrator, e);
      OrganStabilityRow row;
      row.integrator = integrator;
      row.youngsModulusKpa = e;
      // Step 1: bracket. The largest step first (unconditionally stable integrators end here),
      // then the smallest (an integrator unstable at every step ends there).
      auto stable = runsStably(s, config.maxStepS, 1, config.windowS);
      if (!stable) return stable.error();
      ++row.trials;
      if (*stable) {
        row.maxStableStepS = config.maxStepS;
        row.stableAtMaxTested = true;
      } else {
        auto small = runsStably(s, config.minStepS, 1, config.windowS);
        if (!small) return small.error();
        ++row.trials;
        if (*small) {
          // Step 2: bisection in log(step) between a stable lo and an unstable hi.
          double lo = config.minStepS, hi = config.maxStepS;
          for (int i = 0; i < config.bisections; ++i, ++row.trials) {
            const double mid = std::sqrt(lo * hi);
            auto ok = runsStably(s, mid, 1, config.windowS);
            if (!ok) return ok.error();
            (*ok ? lo : hi) = mid;
          }
          row.maxStableStepS = lo;
        }
      }
      // Step 3: the cost of a stable 60 Hz frame: the substeps the limit implies, doubled until
      // the window runs stably (contact and grasp can need more than the free organ), timed.
      if (row.maxStableStepS) {
        int n = std::max(1, static_cast<int>(std::ceil(config.frameS / *row.maxStableStepS)));
        for (; n <= config.maxSubsteps; n *= 2) {
          std::vector<double> ms;
          auto ok = runWindow(s, config.frameS / n, n, config.windowS, &ms);
          if (!ok) return ok.error();
          ++row.trials;
          if (*ok) {
            const auto summary = summarizeSamples(ms);
            row.substepsPerFrame = n;
            row.msPerFrameMedian = summary.median;
            row.msPerFrameMax = summary.max;
            break;
          }
        }
      }
      rows.push_back(row);
    }
  return rows;
}

}  // namespace tissue::scenario
