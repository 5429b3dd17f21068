// tissue-sim stability: the largest stable time step of each integrator for one mass on one
// spring, against stiffness and mass, measured by bisection and compared with the theory
// (tissue/studies/stability_report.h).
#include <cmath>
#include <iostream>

#include "command.h"
#include "output.h"
#include "tissue/core/atomic_file.h"
#include "tissue/studies/stability_report.h"

namespace tissue::sim_app {

void registerStabilityCommand(CLI::App& app, const GlobalOptions& global, int& exitCode) {
  struct Options {
    sim::StabilityStudyConfig config;
    std::string markdown;
    std::string out;
  };
  auto o = std::make_shared<Options>();
  auto* cmd = app.add_subcommand(
      "stability", "largest stable time step of each integrator vs stiffness and mass, against theory");
  cmd->add_option("--masses", o->config.masses, "masses in g (default 0.1 1 10)");
  cmd->add_option("--stiffnesses", o->config.stiffnesses, "spring stiffnesses in N/mm (default 0.01 0.1 1)");
  cmd->add_option("--markdown", o->markdown, "also write the table as markdown to this file");
  cmd->add_option("--out", o->out,
                  "also write DIR/stability.md (table), stability.json, stability_chart.csv and the chart");
  cmd->callback([o, &global, &exitCode] {
    auto positive = [](const std::vector<double>& v) {
      return std::all_of(v.begin(), v.end(), [](double x) { return x > 0.0 && std::isfinite(x); });
    };
    if (!positive(o->config.masses))
      exitCode = fail("stability", "--masses: every mass must be a positive number of grams");
    else if (!positive(o->config.stiffnesses))
      exitCode = fail("stability", "--stiffnesses: every stiffness must be a positive number of N/mm");
    if (exitCode) return;
    const auto r = studies::runStabilityReport(o->config);
    if (!o->markdown.empty())
      if (auto ok = writeTextFileAtomic(o->markdown, r.markdown); !ok) {
        exitCode = fail("stability", ok.error().message);
        return;
      }
    if ((exitCode = writeReportTo("stability", o->out, r.report))) return;
    if (global.json) return printJsonText(global, r.json);
    std::cout << r.markdown << "\n";
    printResult(global, {{"summary", nlohmann::json::parse(r.json)["summary"]}});
  });
}

}  // namespace tissue::sim_app
