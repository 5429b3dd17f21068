// tissue-sim organ-stability: the stability study moved from one spring to the organ. For each
// integrator and Young's modulus, the largest frame step at which the default scenario (the
// volumetric liver under its scripted poke) runs without divergence, the degrade off; and what
// each integrator costs per 60 Hz frame to stay stable (tissue/studies/organ_stability_report.h).
#include "cli_options.h"
#include "command.h"
#include "output.h"
#include "tissue/studies/organ_stability_report.h"

namespace tissue::sim_app {

void registerOrganStabilityCommand(CLI::App& app, const GlobalOptions& global, int& exitCode) {
  struct Options {
    std::string scenario;
    scenario::OrganStabilityConfig config;
    std::filesystem::path out;
  };
  auto o = std::make_shared<Options>();
  auto* cmd = app.add_subcommand(
      "organ-stability", "the largest stable frame step and the 60 Hz cost of each integrator on the organ");
  cmd->add_option("--scenario", o->scenario, "scenario with a tissue block (default: the data liver's)");
  cmd->add_option("--moduli", o->config.youngsModuliKpa, "Young's moduli in kPa (default 2 5 20 80)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--window", o->config.windowS,
                  "simulated seconds per trial (default 3.5: through the deepest poke)")
      ->check(CLI::Range(0.05, 60.0));
  cmd->add_option("--out", o->out, "folder for organ_stability.md, .json and the charts");
  cmd->callback([o, &global, &exitCode] {
    auto r = studies::runOrganStabilityReport(scenarioOrDefault(o->scenario),
                                              {.sharedMeshesDir = sharedDir() / "meshes"}, o->config);
    if (!r) {
      exitCode = fail("organ-stability", r.error().message);
      return;
    }
    if ((exitCode = writeReportTo("organ-stability", o->out, r->report))) return;
    auto j = nlohmann::json::parse(r->json);
    if (!o->out.empty()) {
      j["out"] = o->out.string();
      j["charts"] = nlohmann::json::array();
      for (const auto& chart : r->report.charts)
        j["charts"].push_back(chart.name);
    }
    printResult(global, j);
  });
}

}  // namespace tissue::sim_app
