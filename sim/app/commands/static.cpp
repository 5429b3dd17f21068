// tissue-sim static SCENARIO.json --out POSITIONS.txt: the static equilibrium of the scenario's
// springs, gravity and pins (its instrument and dynamics keys are not used), solved to a force
// tolerance by regularised Newton steps (tissue/sim/static_solve.h); writes one "x y z" line
// (mm) per vertex in the mesh file's vertex order, atomically.
#include <algorithm>
#include <cstdio>
#include <numeric>

#include "cli_options.h"
#include "command.h"
#include "output.h"
#include "tissue/core/atomic_file.h"
#include "tissue/core/stopwatch.h"
#include "tissue/scenario/scenario.h"
#include "tissue/sim/static_solve.h"

namespace tissue::sim_app {
namespace {

struct StaticOptions {
  std::string scenario;
  std::string out;
  double toleranceN = 1e-6;
  int maxIterations = 500;
};

/// One "x y z" line per vertex, ordered by the vertex's index in the mesh file.
std::string positionLines(const std::vector<sim::Vec3d>& x, const std::vector<std::uint32_t>& fileIndex) {
  std::vector<std::uint32_t> order(x.size());
  std::iota(order.begin(), order.end(), 0u);
  std::sort(order.begin(), order.end(),
            [&](std::uint32_t a, std::uint32_t b) { return fileIndex[a] < fileIndex[b]; });
  std::string text;
  text.reserve(x.size() * 48);
  char line[96];
  for (std::uint32_t v : order) {
    std::snprintf(line, sizeof line, "%.9g %.9g %.9g\n", x[v].x, x[v].y, x[v].z);
    text += line;
  }
  return text;
}

int runStatic(const StaticOptions& o, const GlobalOptions& global) {
  if (!(o.toleranceN > 0.0)) return fail("static", "--tolerance: expected a positive force in N");
  if (o.maxIterations < 1) return fail("static", "--max-iterations: expected a positive integer");
  auto parsed = loadScenarioFile("static", o.scenario);
  if (!parsed) return fail("static", parsed.error().message);
  auto mesh = scenario::loadScenarioMesh(*parsed);
  if (!mesh) return fail("static", mesh.error().message);
  auto system = scenario::buildSystem(*parsed, *mesh);
  if (!system) return fail("static", system.error().message);

  Stopwatch clock;
  // A lattice scenario simulates the lattice nodes; the surface follows by the embedding.
  std::vector<sim::Vec3d> x = sim::restState(mesh->simulatedRestPositions()).x;
  const auto report =
      sim::solveStatic(*system, x, {.toleranceN = o.toleranceN, .maxIterations = o.maxIterations});
  const double ms = clock.elapsedMs();
  if (!report.converged)
    return fail("static",
                "did not reach the tolerance " + std::to_string(o.toleranceN) + " N in " +
                    std::to_string(report.iterations) + " iterations (residual " +
                    std::to_string(report.residualN) +
                    " N); raise --max-iterations or --tolerance, or pin the mesh so it cannot drift");
  std::vector<sim::Vec3d> surface = x;
  if (mesh->lattice) {
    std::vector<Float3> embedded(mesh->positions.size());
    sim::embedPositions(*mesh->lattice, x, embedded);
    surface = sim::restState(embedded).x;
  }
  if (auto ok = writeTextFileAtomic(o.out, positionLines(surface, mesh->fileIndex)); !ok)
    return fail("static", ok.error().message);
  printResult(global, {{"scenario", o.scenario},
                       {"out", o.out},
                       {"vertices", surface.size()},
                       {"converged", report.converged},
                       {"iterations", report.iterations},
                       {"accepted_steps", report.acceptedSteps},
                       {"residual_N", report.residualN},
                       {"tolerance_N", o.toleranceN},
                       {"ms", ms}});
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
