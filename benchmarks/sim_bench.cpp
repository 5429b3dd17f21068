// Step costs of the mass-spring simulator on square patches (1 mm spacing, edge and bending
// springs, one edge pinned): the force pass at 1 and 2 threads, and one step of symplectic
// Euler, implicit Euler (CG capped at 100 iterations) and the fast mass-spring solver (10
// local/global iterations, factor cached). Args: grid side, threads. `tissue-sim sim-bench` is the
// command-line counterpart with the table of docs/RESULTS.md.

#include <benchmark/benchmark.h>

#include <vector>

#include "tissue/sim/forces.h"
#include "tissue/sim/integrators.h"
#include "tissue/sim/mass.h"
#include "tissue/sim/spring_network.h"

namespace tissue::sim {
namespace {

struct Patch {
  MassSpringSystem system;
  State rest;
};

/// A side x side patch: 0.1 N/mm edges, 0.02 N/mm bending, 1e-3 g/mm^2, Rayleigh alpha 1 /s.
Patch makePatch(int side, int threads) {
  std::vector<Float3> positions;
  std::vector<Triangle> triangles;
  std::vector<std::uint32_t> pinned;
  auto id = [side](int x, int y) { return static_cast<std::uint32_t>(y * side + x); };
  for (int y = 0; y < side; ++y) {
    pinned.push_back(id(0, y));
    for (int x = 0; x < side; ++x) {
      positions.push_back({float(x), float(y), 0.0f});
      if (x + 1 < side && y + 1 < side) {
        triangles.push_back({id(x, y), id(x + 1, y), id(x + 1, y + 1)});
        triangles.push_back({id(x, y), id(x + 1, y + 1), id(x, y + 1)});
      }
    }
  }
  auto springs =
      buildSurfaceSprings(positions, triangles, {.stiffness = 0.1, .bendingStiffness = 0.02}).value();
  auto masses = computeMasses(positions, triangles, {.total = 0.0, .arealDensity = 1e-3}).value();
  return {makeSystem(std::move(springs), std::move(masses), pinned, {.rayleighMass = 1.0, .threads = threads})
              .value(),
          restState(positions)};
}

void forcePass(benchmark::State& bench) {
  const Patch patch = makePatch(static_cast<int>(bench.range(0)), static_cast<int>(bench.range(1)));
  std::vector<Vec3d> forces(patch.rest.x.size());
  ForceScratch scratch;
  for (auto _ : bench)
    computeForces(patch.system, patch.rest.x, patch.rest.v, forces, scratch);
  bench.counters["springs_per_s"] = benchmark::Counter(
      double(patch.system.springs.size()) * bench.iterations(), benchmark::Counter::kIsRate);
}

void oneStep(benchmark::State& bench, Integrator integrator, double h) {
  const Patch patch = makePatch(static_cast<int>(bench.range(0)), static_cast<int>(bench.range(1)));
  State state = patch.rest;
  StepWorkspace ws;
  const ImplicitSolverConfig solver{.maxIterations = 100, .relativeTolerance = 1e-6};
  step(integrator, patch.system, state, h, ws, solver);  // factors the fast solver's matrix
  for (auto _ : bench)
    step(integrator, patch.system, state, h, ws, solver);
  bench.counters["springs"] = double(patch.system.springs.size());
}

void symplecticEuler(benchmark::State& bench) {
  oneStep(bench, Integrator::SymplecticEuler, 1e-5);
}
void implicitEuler(benchmark::State& bench) {
  oneStep(bench, Integrator::ImplicitEuler, 1.0 / 60.0);
}
void fastMassSpring(benchmark::State& bench) {
  oneStep(bench, Integrator::FastMassSpring, 1.0 / 60.0);
}

BENCHMARK(forcePass)->ArgsProduct({{14, 42, 130, 409}, {1, 2}})->Unit(benchmark::kMillisecond);
BENCHMARK(symplecticEuler)->ArgsProduct({{42, 130, 409}, {1, 2}})->Unit(benchmark::kMillisecond);
BENCHMARK(implicitEuler)->ArgsProduct({{42, 130}, {2}})->Unit(benchmark::kMillisecond);
BENCHMARK(fastMassSpring)->ArgsProduct({{42, 130}, {2}})->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace tissue::sim

BENCHMARK_MAIN();
