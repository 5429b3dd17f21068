// tissue-sim refit-bench: full versus incremental re-fit of the local planes (François §2.2)
// after a local poke and after a global deformation, with the largest deviation between them.
#include <algorithm>
#include <cmath>
#include <iostream>

#include "command.h"
#include "deformations.h"
#include "output.h"
#include "tissue/core/stopwatch.h"
#include "tissue/mesh/deformable_surface.h"
#include "tissue/mesh/load_mesh.h"
#include "tissue/mesh/local_planes.h"
#include "tissue/mesh/vertex_normals.h"

namespace tissue::sim_app {
namespace {

struct BenchOptions {
  std::string meshFile;
  double pokeFraction = 0.05;
  float scale = 1.0f;
  float sigma_t = 1.5f;  // mm^-1, François Table 1 "organs" (smallest channel)
  float epsilon = 0.01f;
  int repeats = 0;  // 0: choose from the mesh size
};

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

/// Times full and incremental re-fits between the rest state and `deformed`, alternating so
/// each incremental update moves the same vertices; returns the figures as JSON.
nlohmann::json measure(std::span<const Float3> rest, std::span<const Float3> deformed,
                       std::span<const Triangle> tris, const mesh::PlaneFitSettings& settings, int repeats) {
  std::vector<Float3> restNormals(rest.size()), defNormals(rest.size());
  mesh::computeVertexNormals(rest, tris, restNormals);
  mesh::computeVertexNormals(deformed, tris, defNormals);
  mesh::IncrementalPlaneFitter fitter(rest, tris, settings);
  fitter.fitAll(rest, restNormals);
  std::vector<Float4> full(rest.size());
  std::vector<double> fullMs, incMs;
  mesh::RefitStats stats;
  double worstAngle = 0.0, worstOffset = 0.0;
  for (int r = 0; r < repeats; ++r) {
    Stopwatch clock;
    mesh::fitVertexPlanes(deformed, defNormals, fitter.neighbourhoods(), full);
    fullMs.push_back(clock.elapsedMs());
    clock.restart();
    stats = fitter.update(deformed, defNormals);
    incMs.push_back(clock.elapsedMs());
    const auto dev = mesh::comparePlanes(fitter.planes(), full);
    worstAngle = std::max(worstAngle, dev.maxAngleRad);
    worstOffset = std::max(worstOffset, dev.maxOffsetMm);
    fitter.update(rest, restNormals);  // back to rest (same vertices move), untimed
  }
  const double f = median(fullMs), i = median(incMs);
  nlohmann::json out;
  out["moved_fraction"] = double(stats.movedVertices) / double(rest.size());
  out["refitted_fraction"] = double(stats.refittedPlanes) / double(rest.size());
  out["full_refit_ms"] = f;
  out["incremental_refit_ms"] = i;
  out["speedup"] = f / std::max(i, 1e-9);
  out["max_normal_deviation_rad"] = worstAngle;
  out["max_offset_deviation_mm"] = worstOffset;
  return out;
}

int run(const BenchOptions& o, const GlobalOptions& global) {
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
  Float3 lo = rest[0], hi = rest[0];
  for (const auto& p : rest) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
  const float size = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
  std::vector<Float3> poked(rest.size()), bent(rest.size());
  applyPoke(rest, normals, topVertex(rest), o.pokeFraction, 0.03f * size, poked);
  applyGlobalBend(rest, 0.05f * size, bent);
  const int repeats = o.repeats > 0 ? o.repeats : int(std::clamp<std::size_t>(2000000 / rest.size(), 5, 200));

  nlohmann::json out = measure(rest, poked, tris, settings, repeats);
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
  out["global"] = measure(rest, bent, tris, settings, std::max(3, repeats / 4));
  printResult(global, out);
  return 0;
}

}  // namespace

void registerRefitBenchCommand(CLI::App& app, const GlobalOptions& global, int& exitCode) {
  auto o = std::make_shared<BenchOptions>();
  auto* cmd = app.add_subcommand("refit-bench", "time full versus incremental re-fit of the local planes");
  cmd->add_option("--mesh", o->meshFile, "mesh file (OBJ, PLY, OFF, STL)")->required();
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
