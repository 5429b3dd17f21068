// tissue-sim static SCENARIO.json --out POSITIONS.txt: the static equilibrium of the scenario's
// springs, gravity and pins (its instrument and dynamics keys are not used), solved to a force
// tolerance by regularised Newton steps (tissue/sim/static_solve.h); writes one "x y z" line
// (mm) per vertex in the mesh file's vertex order, atomically.
#include "cli_options.h"
#include "command.h"
#include "output.h"
#include "tissue/core/atomic_file.h"
#include "tissue/studies/static_solve_run.h"

namespace tissue::sim_app {
namespace {

struct StaticOptions {
  std::string scenario;
  std::string out;
  double toleranceN = 1e-6;
  int maxIterations = 500;
};

int runStatic(const StaticOptions& o, const GlobalOptions& global) {
  if (!(o.toleranceN > 0.0)) return fail("static", "--tolerance: expected a positive force in N");
  if (o.maxIterations < 1) return fail("static", "--max-iterations: expected a positive integer");
  auto parsed = loadScenarioFile("static", o.scenario);
  if (!parsed) return fail("static", parsed.error().message);
  auto solved =
      studies::solveScenarioStatic(*parsed, {.toleranceN = o.toleranceN, .maxIterations = o.maxIterations});
  if (!solved) return fail("static", solved.error().message);
  const sim::StaticSolveReport& report = solved->report;
  if (!report.converged)
    return fail("static",
                "did not reach the tolerance " + std::to_string(o.toleranceN) + " N in " +
                    std::to_string(report.iterations) + " iterations (residual " +
                    std::to_string(report.residualN) +
                    " N); raise --max-iterations or --tolerance, or pin the mesh so it cannot drift");
  if (auto ok = writeTextFileAtomic(o.out, solved->positionLines); !ok)
    return fail("static", ok.error().message);
  auto out = nlohmann::json::parse(solved->json);
  out.update({{"scenario", o.scenario}, {"out", o.out}});
  printResult(global, out);
  return 0;
}

}  // namespace

void registerStaticCommand(CLI::App& app, const GlobalOptions& global, int& exitCode) {
  auto o = std::make_shared<StaticOptions>();
  auto* cmd = app.add_subcommand(
      "static", "static equilibrium of a scenario (springs, gravity, pins) to a force tolerance");
  cmd->add_option("scenario", o->scenario, "scenario file (JSON, docs/SCENARIOS.md)")->required();
  cmd->add_option("--out", o->out, "positions file: one 'x y z' line (mm) per vertex, in file order")
      ->required();
  cmd->add_option("--tolerance", o->toleranceN, "largest force left on a free vertex, N (default 1e-6)");
  cmd->add_option("--max-iterations", o->maxIterations, "Newton steps tried at most (default 500)");
  cmd->callback([o, &global, &exitCode] { exitCode = runStatic(*o, global); });
}

}  // namespace tissue::sim_app
