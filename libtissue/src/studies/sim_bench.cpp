// The integrators' step cost on generated patches, and the force pass alone.
#include "tissue/studies/sim_bench.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "tissue/core/stopwatch.h"
#include "tissue/sim/forces.h"
#include "tissue/sim/mass.h"
#include "tissue/sim/spring_network.h"

namespace tissue::studies {
namespace {

/// The median and the smallest of `times` (ms).
std::pair<double, double> medianAndMin(std::vector<double> times) {
  std::sort(times.begin(), times.end());
  const std::size_t n = times.size();
  const double median = n % 2 ? times[n / 2] : 0.5 * (times[n / 2 - 1] + times[n / 2]);
  return {median, times.front()};
}

}  // namespace

Result<BenchPatch> makeBenchPatch(std::size_t targetSprings, int threads) {
  const int side = static_cast<int>(std::lround(std::sqrt(double(targetSprings) / 6.0))) + 1;
  std::vector<Float3> positions;
  std::vector<Triangle> triangles;
  for (int y = 0; y < side; ++y)
    for (int x = 0; x < side; ++x)
      positions.push_back({float(x), float(y), 0.0f});
  auto id = [side](int x, int y) { return static_cast<std::uint32_t>(y * side + x); };
  std::vector<std::uint32_t> pinned;
  for (int y = 0; y < side; ++y) {
    pinned.push_back(id(0, y));
    for (int x = 0; y + 1 < side && x + 1 < side; ++x) {
      triangles.push_back({id(x, y), id(x + 1, y), id(x + 1, y + 1)});
      triangles.push_back({id(x, y), id(x + 1, y + 1), id(x, y + 1)});
    }
  }
  auto springs = sim::buildSurfaceSprings(positions, triangles,
                                          {.stiffness = 0.1, .bendingStiffness = 0.02, .damping = 1e-6});
  if (!springs) return springs.error();
  auto masses = sim::computeMasses(positions, triangles, {.total = 0.0, .arealDensity = 1e-3});
  if (!masses) return masses.error();
  auto system = sim::makeSystem(std::move(*springs), std::move(*masses), pinned,
                                {.rayleighMass = 1.0, .threads = threads});
  if (!system) return system.error();
  return BenchPatch{std::move(*system), sim::restState(positions)};
}

double omegaBound(const sim::MassSpringSystem& system) {
  const sim::SpringNetwork& s = system.springs;
  std::vector<double> row(system.vertexCount(), 0.0);
  for (std::size_t e = 0; e < s.size(); ++e) {
    const double mi = system.masses[s.i[e]], mj = system.masses[s.j[e]];
    row[s.i[e]] += s.stiffness[e] * (1.0 / mi + 1.0 / std::sqrt(mi * mj));
    row[s.j[e]] += s.stiffness[e] * (1.0 / mj + 1.0 / std::sqrt(mi * mj));
  }
  return row.empty() ? 0.0 : std::sqrt(*std::max_element(row.begin(), row.end()));
}

IntegratorTiming timeIntegrator(sim::Integrator integrator, const BenchPatch& patch, double h,
                                const IntegratorBenchConfig& config) {
  sim::State state = patch.rest;
  sim::StepWorkspace ws;
  const sim::StepStats first = sim::step(integrator, patch.system, state, h, ws, config.solver);
  std::vector<double> times;
  long cg = 0;
  Stopwatch clock;
  while (int(times.size()) < config.maxTimedSteps && (times.empty() || clock.elapsedMs() < config.budgetMs)) {
    Stopwatch one;
    cg += sim::step(integrator, patch.system, state, h, ws, config.solver).cgIterations;
    times.push_back(one.elapsedMs());
  }
  IntegratorTiming r;
  r.integrator = integrator;
  r.springs = patch.system.springs.size();
  r.vertices = patch.system.vertexCount();
  r.stepS = h;
  r.stepsTimed = static_cast<int>(times.size());
  std::tie(r.msPerStep, r.msPerStepBest) = medianAndMin(times);
  r.substepsPerFrame = std::max(1, static_cast<int>(std::ceil(config.frameTimeS / h - 1e-9)));
  r.cgIterationsMean = double(cg) / r.stepsTimed;
  r.factorMsOnce = first.factorMs;
  r.localGlobalIterations = config.solver.localGlobalIterations;
  return r;
}

ForcePassTiming timeForcePass(BenchPatch& patch, int threads) {
  patch.system.config.threads = threads;
  std::vector<sim::Vec3d> forces(patch.system.vertexCount());
  sim::ForceScratch scratch;
  sim::computeForces(patch.system, patch.rest.x, patch.rest.v, forces, scratch);
  std::vector<double> times;
  Stopwatch clock;
  while (times.size() < 1000 && (times.size() < 5 || clock.elapsedMs() < 200.0)) {
    Stopwatch one;
    sim::computeForces(patch.system, patch.rest.x, patch.rest.v, forces, scratch);
    times.push_back(one.elapsedMs());
  }
  ForcePassTiming t;
  t.springs = patch.system.springs.size();
  t.threads = threads;
  std::tie(t.ms, t.msBest) = medianAndMin(times);
  return t;
}

}  // namespace tissue::studies
