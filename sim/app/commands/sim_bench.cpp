// tissue-sim sim-bench: the cost of one step of every integrator on generated patches of about
// 10^3 to 10^6 springs, the force pass alone at 1 and T threads, the per-frame path on the
// data organ and the default scenario in real time (tissue/studies/sim_bench.h).
#include <iostream>

#include "cli_options.h"
#include "command.h"
#include "organ_data.h"
#include "output.h"
#include "tissue/studies/sim_bench.h"

namespace tissue::sim_app {

void registerSimBenchCommand(CLI::App& app, const GlobalOptions& global, int& exitCode) {
  struct Options {
    studies::SimBenchConfig config;
    std::string mesh;
    bool skipFramePath = false;
    std::string scenario;
    std::string scenarioIntegrator;
    bool skipScenario = false;
  };
  auto o = std::make_shared<Options>();
  auto* cmd =
      app.add_subcommand("sim-bench", "step cost of every integrator vs size, force pass, frame path");
  cmd->add_option("--max-springs", o->config.maxSprings,
                  "largest patch, springs (sizes 1e3, 1e4, 1e5, 1e6 up to it)");
  cmd->add_option("--threads", o->config.threads, "threads of the simulator passes (default 2)");
  cmd->add_option("--frames", o->config.framePathFrames, "frames of the frame-path measurement (default 30)");
  cmd->add_option("--mesh", o->mesh, "organ of the frame path (default data/meshes/liver.obj)");
  cmd->add_flag("--skip-frame-path", o->skipFramePath, "only the generated patches");
  cmd->add_option("--scenario", o->scenario,
                  "scenario of the real-time measurement (default data/scenarios/liver_poke_grasp.json)");
  cmd->add_option("--scenario-frames", o->config.scenarioFrames, "its frames (default: the scenario's)");
  cmd->add_option("--scenario-integrator", o->scenarioIntegrator, "its integrator instead of the scenario's");
  cmd->add_flag("--skip-scenario", o->skipScenario, "no scenario measurement");
  cmd->callback([o, &global, &exitCode] {
    auto& c = o->config;
    if (c.threads < 1 || c.threads > 64) {
      exitCode = fail("sim-bench", "--threads must be between 1 and 64");
      return;
    }
    if (c.maxSprings < 1000 || c.framePathFrames < 2) {
      exitCode = fail("sim-bench", "--max-springs must be at least 1000 and --frames at least 2");
      return;
    }
    if (!o->scenarioIntegrator.empty()) {
      auto integrator = parseIntegratorOption("--scenario-integrator", o->scenarioIntegrator);
      if (!integrator) return void(exitCode = fail("sim-bench", integrator.error().message));
      c.scenarioIntegrator = *integrator;
    }
    if (c.scenarioFrames < 0) {
      exitCode = fail("sim-bench", "--scenario-frames must be >= 1 (0: the scenario's)");
      return;
    }
    if (!o->skipFramePath) {
      c.framePathMesh = meshOrDefault(o->mesh);
      if (auto material = readDataMaterial(materialFileFor(c.framePathMesh)))
        c.framePathSigmaTPerMm = scene::firstLayerMinSigmaT(*material);
    }
    if (!o->skipScenario) {
      c.scenario = scenarioOrDefault(o->scenario);
      c.scenarioPaths.sharedMeshesDir = sharedDir() / "meshes";
    }
    auto bench = studies::runSimBench(c);
    if (!bench) {
      exitCode = fail("sim-bench", bench.error().message);
      return;
    }
    if (global.json)
      printJsonText(global, studies::simBenchJson(*bench));
    else
      std::cout << studies::simBenchText(*bench);
  });
}

}  // namespace tissue::sim_app
