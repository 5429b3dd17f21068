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
#include "tissue/sim/integrators.h"
#include "tissue/studies/sim_bench.h"

namespace tissue::sim_app {
namespace {

constexpr double kFrameTime = studies::IntegratorBenchConfig{}.frameTimeS;  ///< s
/// Largest patch the fast solver is run on: the sparse Cholesky factor's fill (AMD ordering)
/// grows about as n^1.5 on these grids: 4.5 million entries at 10^5 springs, over 10^8 (more
/// than a gigabyte, minutes to factor) at 10^6.
constexpr std::size_t kFastSolverMaxSprings = 300000;

nlohmann::json integratorJson(const studies::IntegratorTiming& t) {
  nlohmann::json r;
  r["integrator"] = sim::integratorName(t.integrator);
  r["springs"] = t.springs;
  r["vertices"] = t.vertices;
  r["ms_per_step"] = t.msPerStep;
  r["springs_per_second"] = t.springsPerSecond();
  r["h_s"] = t.stepS;
  r["substeps_per_frame"] = t.substepsPerFrame;
  r["ms_per_frame"] = t.msPerFrame();
  r["ms_per_step_best"] = t.msPerStepBest;
  r["steps_timed"] = t.stepsTimed;
  if (t.integrator == sim::Integrator::ImplicitEuler) r["cg_iterations_mean"] = t.cgIterationsMean;
  if (t.integrator == sim::Integrator::FastMassSpring) {
    r["factor_ms_once"] = t.factorMsOnce;
    r["local_global_iterations"] = t.localGlobalIterations;
  }
  return r;
}

nlohmann::json forcePassJson(const studies::ForcePassTiming& t) {
  return {{"springs", t.springs},
          {"threads", t.threads},
          {"ms", t.ms},
          {"ms_best", t.msBest},
          {"springs_per_second", t.springsPerSecond()},
          {"springs_per_second_best", t.springsPerSecondBest()}};
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
      auto patch = studies::makeBenchPatch(target, o->threads);
      if (!patch) {
        exitCode = fail("sim-bench", patch.error().message);
        return;
      }
      const double explicitH = 0.9 * 2.0 / studies::omegaBound(patch->system);
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
        out["results"].push_back(
            integratorJson(studies::timeIntegrator(integrator, *patch, implicit ? kFrameTime : explicitH)));
      }
      out["force_pass"].push_back(forcePassJson(studies::timeForcePass(*patch, 1)));
      if (o->threads > 1)
        out["force_pass"].push_back(forcePassJson(studies::timeForcePass(*patch, o->threads)));
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
