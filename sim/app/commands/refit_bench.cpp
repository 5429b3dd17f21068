// tissue-sim refit-bench: full versus incremental re-fit of the local planes (François §2.2)
// after a local poke and after a global deformation, with the largest deviation between them;
// with --scenario, frame by frame under the simulator, exact against tolerant (issue 11)
// (tissue/studies/refit_study.h).
#include <iostream>

#include "command.h"
#include "organ_data.h"
#include "output.h"
#include "tissue/mesh/deformable_surface.h"
#include "tissue/studies/refit_study.h"

namespace tissue::sim_app {
namespace {

struct BenchOptions {
  std::string meshFile;
  std::string scenarioFile;
  int frames = 0;  // 0: the scenario's
  double maxNormalErrorRad = mesh::PlaneRefitSettings{}.maxNormalErrorRad;
  double pokeFraction = 0.05;
  float scale = 1.0f;
  float sigma_t = 1.5f;  // mm^-1, François Table 1 "organs" (smallest channel)
  float epsilon = 0.01f;
  int repeats = 0;  // 0: choose from the mesh size
};

/// The simulator drives two surfaces, the exact re-fit (bound 0) and the tolerant one; each
/// frame both are compared with a full re-fit of the simulated positions.
int runScenario(const BenchOptions& o, const GlobalOptions& global) {
  auto parsed = scenario::loadScenario(o.scenarioFile, {.sharedMeshesDir = sharedDir() / "meshes"});
  if (!parsed) return fail("refit-bench", parsed.error().message);
  if (o.frames < 0) return fail("refit-bench", "--frames must be at least 1 (0: the scenario's)");
  if (o.frames > 0) parsed->frames = o.frames;
  auto loaded = mesh::loadMesh(parsed->mesh, {.requireUvs = true, .scaleToMm = float(parsed->meshScaleToMm)});
  if (!loaded) return fail("refit-bench", loaded.error().message);
  auto material = readDataMaterial(materialFileFor(parsed->mesh));
  const mesh::PlaneFitSettings settings{
      .sigma_t = material ? scene::firstLayerMinSigmaT(*material) : o.sigma_t, .epsilon = o.epsilon};
  auto study =
      studies::studyRefitUnderScenario(*parsed, *loaded, settings, o.maxNormalErrorRad, parsed->frames);
  if (!study) {
    const std::string& m = study.error().message;
    return fail("refit-bench", m.rfind("the simulated mesh", 0) == 0 ? o.scenarioFile + ": " + m : m);
  }
  auto out = nlohmann::json::parse(studies::scenarioRefitJson(*study));
  out.update(
      {{"scenario", o.scenarioFile}, {"mesh", parsed->mesh.string()}, {"radius_mm", settings.radiusMm()}});
  printResult(global, out);
  return 0;
}

int run(const BenchOptions& o, const GlobalOptions& global) {
  if (!(o.maxNormalErrorRad >= 0.0))
    return fail("refit-bench", "--max-normal-error must be >= 0 rad (0: exact); give e.g. 1e-4");
  if (!o.scenarioFile.empty()) return runScenario(o, global);
  if (o.meshFile.empty())
    return fail("refit-bench", "give --mesh FILE (a poke and a bend) or --scenario FILE");
  auto loaded = mesh::loadMesh(o.meshFile, {.scaleToMm = o.scale});
  if (!loaded) return fail("refit-bench", loaded.error().message);
  if (!(o.pokeFraction > 0.0 && o.pokeFraction <= 1.0))
    return fail("refit-bench",
                "--poke-fraction " + std::to_string(o.pokeFraction) + " is outside (0, 1]; give e.g. 0.05");
  const mesh::PlaneFitSettings settings{.sigma_t = o.sigma_t, .epsilon = o.epsilon};
  if (!(settings.sigma_t > 0.0f) || !(settings.epsilon > 0.0f && settings.epsilon < 1.0f))
    return fail("refit-bench", "--sigma-t must be > 0 mm^-1 and --epsilon in (0, 1)");
  const auto bench = studies::benchRefitOnMesh(mesh::geometricPositionsOf(*loaded),
                                               mesh::geometricTrianglesOf(*loaded), settings, o.pokeFraction,
                                               o.repeats, {.maxNormalErrorRad = o.maxNormalErrorRad});
  if (bench.meanNeighbourhood > 200.0)
    std::cerr << "tissue-sim refit-bench: warning: the neighbourhood sphere (r = " << settings.radiusMm()
              << " mm) holds " << bench.meanNeighbourhood
              << " vertices on average; is the mesh in mm? pass --scale (mm per file unit)\n";
  auto out = nlohmann::json::parse(studies::meshRefitBenchJson(bench));
  out["mesh"] = o.meshFile;
  printResult(global, out);
  return 0;
}

}  // namespace

void registerRefitBenchCommand(CLI::App& app, const GlobalOptions& global, int& exitCode) {
  auto o = std::make_shared<BenchOptions>();
  auto* cmd = app.add_subcommand("refit-bench", "time full versus incremental re-fit of the local planes");
  cmd->add_option("--mesh", o->meshFile, "mesh file (OBJ, PLY, OFF, STL): a procedural poke and bend");
  cmd->add_option(
      "--scenario", o->scenarioFile,
      "scenario file (JSON): the simulator moves the surface, frame by frame (instead of --mesh)");
  cmd->add_option("--frames", o->frames, "with --scenario: frames to run (default: the scenario's)");
  cmd->add_option("--max-normal-error", o->maxNormalErrorRad,
                  "bound of the tolerant re-fit, rad (default 1e-4; 0: exact)");
  cmd->add_option("--poke-fraction", o->pokeFraction,
                  "fraction of vertices the local poke moves (default 0.05)");
  cmd->add_option("--scale", o->scale, "mm per file unit (default 1)");
  cmd->add_option("--sigma-t", o->sigma_t, "extinction of the first layer, mm^-1 (default 1.5)");
  cmd->add_option("--epsilon", o->epsilon,
                  "attenuation threshold of the neighbourhood sphere (default 0.01)");
  cmd->add_option("--repeats", o->repeats, "timed repetitions (default: from the mesh size)");
  cmd->callback([o, &global, &exitCode] { exitCode = run(*o, global); });
}

}  // namespace tissue::sim_app
