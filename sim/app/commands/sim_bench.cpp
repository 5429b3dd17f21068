// tissue-sim sim-bench: the cost of one step of every integrator on generated patches of about
// 10^3 to 10^6 springs, the force pass alone at 1 and T threads, the per-frame path on the
// data organ (commands/sim_bench_frame_path.cpp) and the default scenario in real time
// (commands/sim_bench_scenario.cpp: ms per frame median/p99/max, force-update rate).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <optional>
#include <utility>
#include <vector>

#include "command.h"
#include "output.h"
#include "sim_bench.h"
#include "tissue/core/stopwatch.h"
#include "tissue/sim/forces.h"
#include "tissue/sim/integrators.h"
#include "tissue/sim/mass.h"
#include "tissue/sim/spring_network.h"

namespace tissue::sim_app {
namespace {

constexpr double kFrameTime = 1.0 / 60.0;  ///< s
constexpr double kBudgetMs = 300.0;        ///< timing budget per integrator and size
constexpr int kMaxTimedSteps = 200;
/// Largest patch the fast solver is run on: the sparse Cholesky factor's fill (AMD ordering)
/// grows about as n^1.5 on these grids: 4.5 million entries at 10^5 springs, over 10^8 (more
/// than a gigabyte, minutes to factor) at 10^6.
constexpr std::size_t kFastSolverMaxSprings = 300000;

/// A square patch, 1 mm spacing, of about `targetSprings` springs (edge and bending springs,
/// about 6 per vertex): 0.1 N/mm edges, 0.02 N/mm bending, 1e-6 N*s/mm spring damping,
/// 1e-3 g/mm^2 (1 mm of 1 g/cm^3), Rayleigh alpha 1 /s, gravity, the x = 0 column pinned.
struct BenchPatch {
  sim::MassSpringSystem system;
  sim::State rest;
};

Result<BenchPatch> makePatch(std::size_t targetSprings, int threads) {
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

}  // namespace

double omegaBound(const sim::MassSpringSystem& system) {
  const sim::SpringNetwork& s = system.springs;
  std::vector<double> row(system.vertexCount(), 0.0);
  for (std::size_t e = 0; e < s.size(); ++e) {
    const double mi = system.masses[s.i[e]], mj = system.masses[s.j[e]];
    row[s.i[e]] += s.stiffness[e] * (1.0 / mi + 1.0 / std::sqrt(mi * mj));
    row[s.j[e]] += s.stiffness[e] * (1.0 / mj + 1.0 / std::sqrt(mi * mj));
  }
  return std::sqrt(*std::max_element(row.begin(), row.end()));
}

namespace {

/// The median and the smallest of `times` (ms).
std::pair<double, double> medianAndMin(std::vector<double> times) {
  std::sort(times.begin(), times.end());
  const std::size_t n = times.size();
  const double median = n % 2 ? times[n / 2] : 0.5 * (times[n / 2 - 1] + times[n / 2]);
  return {median, times.front()};
}

/// Times steps of `integrator` at step h from rest, after one untimed step (which factors the
/// fast solver's matrix and warms the conjugate gradients).
nlohmann::json timeIntegrator(sim::Integrator integrator, const BenchPatch& patch, double h) {
  const sim::ImplicitSolverConfig solver{.maxIterations = 100, .relativeTolerance = 1e-6};
  sim::State state = patch.rest;
  sim::StepWorkspace ws;
  const sim::StepStats first = sim::step(integrator, patch.system, state, h, ws, solver);
  // Per-step times; the median and the best resist the noise of a shared machine.
  std::vector<double> times;
  long cg = 0;
  Stopwatch clock;
  while (int(times.size()) < kMaxTimedSteps && (times.empty() || clock.elapsedMs() < kBudgetMs)) {
    Stopwatch one;
    cg += sim::step(integrator, patch.system, state, h, ws, solver).cgIterations;
    times.push_back(one.elapsedMs());
  }
  const int steps = static_cast<int>(times.size());
  const auto [msPerStep, bestMs] = medianAndMin(times);
  const int substeps = std::max(1, static_cast<int>(std::ceil(kFrameTime / h - 1e-9)));
  nlohmann::json r;
  r["integrator"] = sim::integratorName(integrator);
  r["springs"] = patch.system.springs.size();
  r["vertices"] = patch.system.vertexCount();
  r["ms_per_step"] = msPerStep;
  r["springs_per_second"] = double(patch.system.springs.size()) / (msPerStep * 1e-3);
  r["h_s"] = h;
  r["substeps_per_frame"] = substeps;
  r["ms_per_frame"] = msPerStep * substeps;
  r["ms_per_step_best"] = bestMs;
  r["steps_timed"] = steps;
  if (integrator == sim::Integrator::ImplicitEuler) r["cg_iterations_mean"] = double(cg) / steps;
  if (integrator == sim::Integrator::FastMassSpring) {
    r["factor_ms_once"] = first.factorMs;
    r["local_global_iterations"] = solver.localGlobalIterations;
  }
  return r;
}

/// The force pass alone (springs with damping, gravity, Rayleigh) at `threads` threads.
nlohmann::json timeForcePass(BenchPatch& patch, int threads) {
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
  const auto [ms, bestMs] = medianAndMin(times);
  return {{"springs", patch.system.springs.size()},
          {"threads", threads},
          {"ms", ms},
          {"ms_best", bestMs},
          {"springs_per_second", double(patch.system.springs.size()) / (ms * 1e-3)},
          {"springs_per_second_best", double(patch.system.springs.size()) / (bestMs * 1e-3)}};
}

void printText(const nlohmann::json& out) {
  std::printf("%-18s %9s %11s %12s %9s %12s\n", "integrator", "springs", "ms/step", "Msprings/s", "substeps",
              "ms/frame");
  for (const auto& r : out["results"]) {
    if (r["ms_per_step"].is_null()) {
      std::printf("%-18s %9zu  skipped: %s\n", r["integrator"].get<std::string>().c_str(),
                  r["springs"].get<std::size_t>(), r["skipped"].get<std::string>().c_str());
      continue;
    }
    std::printf("%-18s %9zu %11.4f %12.2f %9d %12.3f\n", r["integrator"].get<std::string>().c_str(),
                r["springs"].get<std::size_t>(), r["ms_per_step"].get<double>(),
                r["springs_per_second"].get<double>() * 1e-6, r["substeps_per_frame"].get<int>(),
                r["ms_per_frame"].get<double>());
  }
  std::printf("\nforce pass (median; best):\n%9s %8s %10s %12s %12s\n", "springs", "threads", "ms",
              "Msprings/s", "best");
  for (const auto& r : out["force_pass"])
    std::printf("%9zu %8d %10.4f %12.2f %12.2f\n", r["springs"].get<std::size_t>(), r["threads"].get<int>(),
                r["ms"].get<double>(), r["springs_per_second"].get<double>() * 1e-6,
                r["springs_per_second_best"].get<double>() * 1e-6);
  if (out.contains("frame_path")) std::cout << "\nframe path:\n" << out["frame_path"].dump(2) << "\n";
  if (out.contains("scenario")) {
    const auto& s = out["scenario"];
    std::printf(
        "\nscenario %s (%s, %d substeps, %zu nodes, %zu springs, %d frames):\n"
        "  ms per frame  median %.3f  p99 %.3f  max %.3f\n"
        "  ms per substep median %.4f  p99 %.4f  max %.4f\n"
        "  force updates %.0f Hz   divergence events %ld   degraded frames %ld   max force %.3f N   "
        "max refactor %.3f ms\n",
        s["scenario"].get<std::string>().c_str(), s["integrator"].get<std::string>().c_str(),
        s["substeps"].get<int>(), s["simulated_vertices"].get<std::size_t>(), s["springs"].get<std::size_t>(),
        s["frames"].get<int>(), s["frame_ms"]["median"].get<double>(), s["frame_ms"]["p99"].get<double>(),
        s["frame_ms"]["max"].get<double>(), s["substep_ms"]["median"].get<double>(),
        s["substep_ms"]["p99"].get<double>(), s["substep_ms"]["max"].get<double>(),
        s["force_update_hz"].get<double>(), s["divergence_events"].get<long>(),
        s["degraded_frames"].get<long>(), s["max_force_N"].get<double>(), s["max_factor_ms"].get<double>());
  }
}

}  // namespace

void registerSimBenchCommand(CLI::App& app, const GlobalOptions& global, int& exitCode) {
  struct Options {
    std::size_t maxSprings = 1000000;
    int threads = 2;
    int frames = 30;
    std::string mesh;
    bool skipFramePath = false;
    std::string scenario;
    int scenarioFrames = 0;
    std::string scenarioIntegrator;
    bool skipScenario = false;
  };
  auto o = std::make_shared<Options>();
  auto* cmd =
      app.add_subcommand("sim-bench", "step cost of every integrator vs size, force pass, frame path");
  cmd->add_option("--max-springs", o->maxSprings,
                  "largest patch, springs (sizes 1e3, 1e4, 1e5, 1e6 up to it)");
  cmd->add_option("--threads", o->threads, "threads of the simulator passes (default 2)");
  cmd->add_option("--frames", o->frames, "frames of the frame-path measurement (default 30)");
  cmd->add_option("--mesh", o->mesh, "organ of the frame path (default data/meshes/liver.obj)");
  cmd->add_flag("--skip-frame-path", o->skipFramePath, "only the generated patches");
  cmd->add_option("--scenario", o->scenario,
                  "scenario of the real-time measurement (default data/scenarios/liver_poke_grasp.json)");
  cmd->add_option("--scenario-frames", o->scenarioFrames, "its frames (default: the scenario's)");
  cmd->add_option("--scenario-integrator", o->scenarioIntegrator, "its integrator instead of the scenario's");
  cmd->add_flag("--skip-scenario", o->skipScenario, "no scenario measurement");
  cmd->callback([o, &global, &exitCode] {
    if (o->threads < 1 || o->threads > 64) {
      exitCode = fail("sim-bench", "--threads must be between 1 and 64");
      return;
    }
    if (o->maxSprings < 1000 || o->frames < 2) {
      exitCode = fail("sim-bench", "--max-springs must be at least 1000 and --frames at least 2");
      return;
    }
    std::optional<sim::Integrator> scenarioIntegrator;
    if (!o->scenarioIntegrator.empty()) {
      scenarioIntegrator = sim::parseIntegrator(o->scenarioIntegrator);
      if (!scenarioIntegrator) {
        exitCode =
            fail("sim-bench", "--scenario-integrator: unknown integrator \"" + o->scenarioIntegrator +
                                  "\"; give explicit-euler, symplectic-euler, verlet, implicit-euler or "
                                  "fast-mass-spring");
        return;
      }
    }
    if (o->scenarioFrames < 0) {
      exitCode = fail("sim-bench", "--scenario-frames must be >= 1 (0: the scenario's)");
      return;
    }
    nlohmann::json out;
    out["threads"] = o->threads;
    out["frame_time_s"] = kFrameTime;
    out["model"] =
        "square patch, 1 mm spacing, edge springs 0.1 N/mm + bending 0.02 N/mm, damping 1e-6 N*s/mm, "
        "1e-3 g/mm^2, Rayleigh alpha 1/s, gravity, one edge pinned; explicit integrators at 0.9 of the "
        "Gershgorin bound 2/omega_max, implicit ones one step per 1/60 s frame; implicit Euler CG <= 100 "
        "iterations to 1e-6; fast-mass-spring 10 iterations";
    out["results"] = nlohmann::json::array();
    out["force_pass"] = nlohmann::json::array();
    Stopwatch total;
    for (std::size_t target :
         {std::size_t{1000}, std::size_t{10000}, std::size_t{100000}, std::size_t{1000000}}) {
      if (target > o->maxSprings) break;
      auto patch = makePatch(target, o->threads);
      if (!patch) {
        exitCode = fail("sim-bench", patch.error().message);
        return;
      }
      const double explicitH = 0.9 * 2.0 / omegaBound(patch->system);
      for (sim::Integrator integrator :
           {sim::Integrator::ExplicitEuler, sim::Integrator::SymplecticEuler, sim::Integrator::VelocityVerlet,
            sim::Integrator::ImplicitEuler, sim::Integrator::FastMassSpring}) {
        const bool implicit =
            integrator == sim::Integrator::ImplicitEuler || integrator == sim::Integrator::FastMassSpring;
        if (integrator == sim::Integrator::FastMassSpring &&
            patch->system.springs.size() > kFastSolverMaxSprings) {
          out["results"].push_back({{"integrator", sim::integratorName(integrator)},
                                    {"springs", patch->system.springs.size()},
                                    {"ms_per_step", nullptr},
                                    {"springs_per_second", nullptr},
                                    {"skipped", "factor too large for this machine (fill grows as n^1.5)"}});
          continue;
        }
        out["results"].push_back(timeIntegrator(integrator, *patch, implicit ? kFrameTime : explicitH));
      }
      out["force_pass"].push_back(timeForcePass(*patch, 1));
      if (o->threads > 1) out["force_pass"].push_back(timeForcePass(*patch, o->threads));
    }
    if (!o->skipFramePath) {
      const auto mesh = o->mesh.empty() ? dataDir() / "meshes" / "liver.obj" : std::filesystem::path(o->mesh);
      auto framePath = measureFramePath({.mesh = mesh, .frames = o->frames, .threads = o->threads});
      if (!framePath) {
        exitCode = fail("sim-bench", framePath.error().message);
        return;
      }
      out["frame_path"] = *framePath;
    }
    if (!o->skipScenario) {
      const auto file = o->scenario.empty() ? dataDir() / "scenarios" / "liver_poke_grasp.json"
                                            : std::filesystem::path(o->scenario);
      auto measured = measureScenario({.scenario = file,
                                       .sharedMeshesDir = sharedDir() / "meshes",
                                       .frames = o->scenarioFrames,
                                       .integrator = scenarioIntegrator});
      if (!measured) {
        exitCode = fail("sim-bench", measured.error().message);
        return;
      }
      out["scenario"] = *measured;
    }
    out["bench_s"] = total.elapsedMs() * 1e-3;
    if (global.json)
      printResult(global, out);
    else
      printText(out);
    exitCode = 0;
  });
}

}  // namespace tissue::sim_app
