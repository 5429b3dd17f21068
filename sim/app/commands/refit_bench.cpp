// tissue-sim refit-bench: full versus incremental re-fit of the local planes (François §2.2)
// after a local poke and after a global deformation, with the largest deviation between them;
// with --scenario, frame by frame under the simulator, exact against tolerant (issue 11).
#include <algorithm>
#include <iostream>

#include "command.h"
#include "organ_data.h"
#include "output.h"
#include "tissue/core/vec_math.h"
#include "tissue/mesh/deformable_surface.h"
#include "tissue/mesh/load_mesh.h"
#include "tissue/mesh/local_planes.h"
#include "tissue/mesh/vertex_normals.h"
#include "tissue/scenario/scenario.h"
#include "tissue/studies/deformations.h"
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

/// The re-fit comparison between the rest state and `deformed` as JSON.
nlohmann::json measure(std::span<const Float3> rest, std::span<const Float3> deformed,
                       std::span<const Triangle> tris, const mesh::PlaneFitSettings& settings, int repeats,
                       const mesh::PlaneRefitSettings& refit) {
  const studies::RefitComparison c = studies::compareRefits(rest, deformed, tris, settings, repeats, refit);
  nlohmann::json out;
  out["moved_fraction"] = c.movedFraction;
  out["refitted_fraction"] = c.exact.refittedFraction;
  out["full_refit_ms"] = c.fullRefitMs;
  out["incremental_refit_ms"] = c.exact.refitMs;
  out["speedup"] = c.speedup();
  out["max_normal_deviation_rad"] = c.exact.maxNormalDeviationRad;
  out["max_offset_deviation_mm"] = c.exact.maxOffsetDeviationMm;
  out["tolerant"] = {{"max_normal_error_rad", refit.maxNormalErrorRad},
                     {"refitted_fraction", c.tolerant.refittedFraction},
                     {"refit_ms", c.tolerant.refitMs},
                     {"max_normal_deviation_rad", c.tolerant.maxNormalDeviationRad},
                     {"max_offset_deviation_mm", c.tolerant.maxOffsetDeviationMm}};
  return out;
}

nlohmann::json seriesJson(const studies::RefitSeries& r) {
  return {{"max_normal_error_rad", r.maxNormalErrorRad},
          {"mean_refitted_fraction", r.meanRefittedFraction},
          {"planes_ms_median", r.planesMsMedian},
          {"planes_ms_p99", r.planesMsP99},
          {"planes_ms_max", r.planesMsMax},
          {"max_normal_deviation_rad", r.maxNormalDeviationRad},
          {"max_offset_deviation_mm", r.maxOffsetDeviationMm}};
}

/// The simulator drives two surfaces, the exact re-fit (bound 0) and the tolerant one; each
/// frame both are compared with a full re-fit of the simulated positions.
int runScenario(const BenchOptions& o, const GlobalOptions& global) {
  auto parsed = scenario::loadScenario(o.scenarioFile, {.sharedMeshesDir = sharedDir() / "meshes"});
  if (!parsed) return fail("refit-bench", parsed.error().message);
  if (o.frames < 0) return fail("refit-bench", "--frames must be at least 1 (0: the scenario's)");
  if (o.frames > 0) parsed->frames = o.frames;
  if (!(o.maxNormalErrorRad >= 0.0))
    return fail("refit-bench", "--max-normal-error must be >= 0 rad (0: exact); give e.g. 1e-4");
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
  nlohmann::json out;
  out["scenario"] = o.scenarioFile;
  out["mesh"] = parsed->mesh.string();
  out["vertices"] = study->vertices;
  out["frames"] = study->frames;
  out["radius_mm"] = settings.radiusMm();
  out["mean_changed_vertex_fraction"] = study->meanChangedVertexFraction;
  nlohmann::json steps = nlohmann::json::object();
  for (std::size_t k = 0; k < studies::kRefitMotionStepsMm.size(); ++k)
    steps[std::to_string(studies::kRefitMotionStepsMm[k]) + "_mm"] = study->meanFractionBeyond[k];
  out["mean_fraction_moving_per_frame_beyond"] = steps;
  out["plane_tolerance_mm"] = {
      {"p10", study->toleranceMmP10}, {"median", study->toleranceMmMedian}, {"p90", study->toleranceMmP90}};
  out["normals_ms_median"] = study->normalsMsMedian;
  out["tangents_ms_median"] = study->tangentsMsMedian;
  out["full_refit_ms_median"] = study->fullRefitMsMedian;
  out["exact"] = seriesJson(study->exact);
  out["tolerant"] = seriesJson(study->tolerant);
  printResult(global, out);
  return 0;
}

int run(const BenchOptions& o, const GlobalOptions& global) {
  if (!o.scenarioFile.empty()) return runScenario(o, global);
  if (o.meshFile.empty())
    return fail("refit-bench", "give --mesh FILE (a poke and a bend) or --scenario FILE");
  if (!(o.maxNormalErrorRad >= 0.0))
    return fail("refit-bench", "--max-normal-error must be >= 0 rad (0: exact); give e.g. 1e-4");
  const mesh::PlaneRefitSettings refit{.maxNormalErrorRad = o.maxNormalErrorRad};
  auto loaded = mesh::loadMesh(o.meshFile, {.scaleToMm = o.scale});
  if (!loaded) return fail("refit-bench", loaded.error().message);
  if (!(o.pokeFraction > 0.0 && o.pokeFraction <= 1.0))
    return fail("refit-bench",
                "--poke-fraction " + std::to_string(o.pokeFraction) + " is outside (0, 1]; give e.g. 0.05");
  const mesh::PlaneFitSettings settings{.sigma_t = o.sigma_t, .epsilon = o.epsilon};
  if (!(settings.sigma_t > 0.0f) || !(settings.epsilon > 0.0f && settings.epsilon < 1.0f))
    return fail("refit-bench", "--sigma-t must be > 0 mm^-1 and --epsilon in (0, 1)");
  const auto rest = mesh::geometricPositionsOf(*loaded);
  const auto tris = mesh::geometricTrianglesOf(*loaded);
  std::vector<Float3> normals(rest.size());
  mesh::computeVertexNormals(rest, tris, normals);
  // A poke as deep as a tenth of the poked region's extent, at the top of the mesh.
  const Bounds3 box = boundsOf(rest);
  const Float3 lo = box.lo, hi = box.hi;
  const float size = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
  std::vector<Float3> poked(rest.size()), bent(rest.size());
  studies::applyPoke(rest, normals, studies::topVertex(rest), o.pokeFraction, 0.03f * size, poked);
  studies::applyGlobalBend(rest, 0.05f * size, bent);
  const int repeats = o.repeats > 0 ? o.repeats : int(std::clamp<std::size_t>(2000000 / rest.size(), 5, 200));

  nlohmann::json out = measure(rest, poked, tris, settings, repeats, refit);
  out["mesh"] = o.meshFile;
  out["vertices"] = rest.size();
  out["radius_mm"] = settings.radiusMm();
  out["sigma_t_per_mm"] = settings.sigma_t;
  out["epsilon"] = settings.epsilon;
  out["mean_neighbourhood"] = 0.0;
  {
    mesh::IncrementalPlaneFitter probe(rest, tris, settings);
    out["mean_neighbourhood"] = double(probe.neighbourhoods().indices.size()) / double(rest.size());
  }
  out["repeats"] = repeats;
  if (out["mean_neighbourhood"].get<double>() > 200.0) {
    std::cerr << "tissue-sim refit-bench: warning: the neighbourhood sphere (r = " << settings.radiusMm()
              << " mm) holds " << out["mean_neighbourhood"].get<double>()
              << " vertices on average; is the mesh in mm? pass --scale (mm per file unit)\n";
  }
  out["global"] = measure(rest, bent, tris, settings, std::max(3, repeats / 4), refit);
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
