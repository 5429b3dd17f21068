// tissue-sim budget-bench [--out DIR] [--budgets MS,MS,...] [--width W --height H]
// [--truth-seconds S] [--frames N] --json: a scene of five livers (the poked one in close-up, two
// at mid distance, two far and small), the close-up deformed by the replayed
// data/sessions/liver_poke_grasp.json, under frame budgets with the quality controller choosing each organ's
// method and setting, against every single setting on all organs; errors against the path-traced truth (issue
// 16). The bench is tissue::studies' (studies/budget_bench.h); this command parses and prints.

#include <cstdio>

#include "../organ_data.h"
#include "cli_options.h"
#include "command.h"
#include "output.h"
#include "report_output.h"
#include "tissue/studies/budget_bench.h"

namespace tissue::sim_app {
namespace {

struct BudgetBenchOptions {
  ReportPlaces places;  // --out: budget_bench.md, .json, budget_bench.png
  studies::BudgetBenchConfig config;
};

int run(BudgetBenchOptions o, const GlobalOptions& global) {
  const std::filesystem::path table = o.config.scene.qualityTable;
  o.config.scene = dataSceneSettings();
  o.config.scene.qualityTable = table;
  o.config.mesh = dataDir() / "meshes" / "liver.obj";
  o.config.material = dataDir() / "materials" / "liver.json";
  o.config.session = dataDir() / "sessions" / "liver_poke_grasp.json";
  if (!o.places.out.empty() && o.config.truthCacheDir.empty())
    o.config.truthCacheDir = std::filesystem::path(o.places.out) / "truth_cache";
  o.config.onProgress = [](const std::string& line) {
    std::fprintf(stderr, "budget-bench: %s\n", line.c_str());
  };
  auto bench = studies::runBudgetBench(o.config);
  if (!bench) return fail("budget-bench", bench.error().message);
  return finishStudy("budget-bench", std::move(bench->output), o.places, global);
}

}  // namespace

void registerBudgetBenchCommand(CLI::App& app, const GlobalOptions& global, int& exitCode) {
  auto o = std::make_shared<BudgetBenchOptions>();
  auto* cmd = app.add_subcommand("budget-bench",
                                 "the quality controller under frame budgets against the best fixed setting");
  cmd->add_option("--out", o->places.out, "folder for the report: budget_bench.md, .json, .png (created)");
  cmd->add_option("--budgets", o->config.budgetsMs,
                  "frame budgets, ms (default: three from the fixed settings' times)")
      ->delimiter(',');
  addImageSizeOptions(cmd, o->config.width, o->config.height);
  cmd->add_option("--truth-seconds", o->config.truthSeconds, "truth time at most, s (default 120)");
  cmd->add_option("--spp", o->config.truthSpp, "truth samples per pixel at most (default 4096)");
  cmd->add_option("--truth-cache", o->config.truthCacheDir,
                  "folder of truth images, named by what they depend on (default <out>/truth_cache)");
  cmd->add_option("--frames", o->config.timedFrames, "timed frames per run (default 60)");
  cmd->add_option("--warmup", o->config.warmupFrames, "untimed frames per run first (default 40)");
  cmd->add_option("--quality-table", o->config.scene.qualityTable, "an atlas JSON as the controller's table");
  cmd->add_flag("--artist-terms", o->config.artistTerms,
                "score with the ambient fill light and the normal maps, which the truth lacks (default off)");
  cmd->callback([o, &global, &exitCode] { exitCode = run(*o, global); });
}

}  // namespace tissue::sim_app
