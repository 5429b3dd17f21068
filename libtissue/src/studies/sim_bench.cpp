// The integrators' step cost on generated patches, and the force pass alone.
#include "tissue/studies/sim_bench.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include <cstdarg>
#include <cstdio>

#include "json_text.h"
#include "tissue/core/stopwatch.h"
#include "tissue/mesh/deformable_surface.h"
#include "tissue/mesh/load_mesh.h"
#include "tissue/mesh/vertex_normals.h"
#include "tissue/scenario/scenario_run.h"
#include "tissue/sim/forces.h"
#include "tissue/sim/mass.h"
#include "tissue/sim/spring_network.h"
#include "tissue/studies/deformations.h"

namespace tissue::studies {
namespace {

/// The median and the smallest of `times` (ms).
std::pair<double, double> medianAndMin(const std::vector<double>& times) {
  return {summarizeSamples(times).median, *std::min_element(times.begin(), times.end())};
}

/// The data organ's springs and masses for the frame path (FramePathBench).
Result<sim::MassSpringSystem> organSystem(std::span<const Float3> rest, std::span<const Triangle> triangles,
                                          int threads) {
  auto springs = sim::buildSurfaceSprings(rest, triangles,
                                          {.stiffness = 0.1, .bendingStiffness = 0.02, .damping = 1e-5});
  if (!springs) return springs.error();
  auto masses = sim::computeMasses(rest, triangles, {.total = 0.0, .arealDensity = 0.0106});
  if (!masses) return masses.error();
  float zMin = rest[0].z, zMax = rest[0].z;
  for (const Float3& p : rest)
    zMin = std::min(zMin, p.z), zMax = std::max(zMax, p.z);
  std::vector<std::uint32_t> pinned;  // as if the organ rested on a support, which carries it
  for (std::size_t v = 0; v < rest.size(); ++v)
    if (rest[v].z < zMin + 0.1f * (zMax - zMin)) pinned.push_back(static_cast<std::uint32_t>(v));
  return sim::makeSystem(std::move(*springs), std::move(*masses), pinned,
                         {.gravity = {}, .rayleighMass = 2.0, .threads = threads});
}

Result<FramePathTiming> timeFramePath(const SurfaceMesh& loaded, sim::Integrator integrator, float sigmaT,
                                      const FramePathBench& bench, int threads) {
  auto surface = mesh::DeformableSurface::create(loaded, {.sigma_t = sigmaT, .epsilon = 0.01f},
                                                 static_cast<unsigned>(threads));
  if (!surface) return surface.error();
  const auto rest = surface->geometricRestPositions();
  auto system = organSystem(rest, surface->geometricTriangles(), threads);
  if (!system) return system.error();
  // Released from a poke: the top 5% pushed in 8 mm, then let go.
  std::vector<Float3> normals(rest.size()), poked(rest.size());
  mesh::computeVertexNormals(rest, surface->geometricTriangles(), normals);
  applyPoke(rest, normals, topVertex(rest), 0.05, 8.0f, poked);
  sim::State state = sim::restState(poked);
  for (std::size_t v = 0; v < rest.size(); ++v)
    if (system->invMasses[v] == 0.0) state.x[v] = {rest[v].x, rest[v].y, rest[v].z};
  sim::StepWorkspace ws;
  const sim::ImplicitSolverConfig solver{.maxIterations = 100, .relativeTolerance = 1e-6};
  (void)surface->update(sim::toFloat3(state.x));
  FramePathTiming t{.integrator = integrator, .vertices = rest.size(), .springs = system->springs.size()};
  const double frame = bench.frameTimeS;
  if (integrator == sim::Integrator::SymplecticEuler)
    t.substepsPerFrame = static_cast<int>(std::ceil(frame / (0.9 * 2.0 / omegaBound(*system))));
  int stepFrames = 0;
  for (int f = 0; f < bench.frames; ++f) {
    Stopwatch clock;
    sim::StepStats stats;
    for (int k = 0; k < t.substepsPerFrame; ++k)
      stats = sim::step(integrator, *system, state, frame / t.substepsPerFrame, ws, solver);
    const std::vector<Float3> positions = sim::toFloat3(state.x);
    if (stats.refactored) {
      t.factorMsOnce = stats.factorMs;  // the one-off factorisation is reported on its own
    } else {
      t.simulateMs += clock.elapsedMs();
      ++stepFrames;
    }
    const auto update = surface->update(positions, bench.moveToleranceMm);
    t.positionsInMs += update.gatherMs, t.normalsMs += update.normalsMs, t.planesMs += update.planesMs,
        t.tangentsMs += update.tangentsMs;
    t.meanRefittedPlaneFraction += double(update.refit.refittedPlanes) / double(rest.size());
  }
  const double n = bench.frames;
  t.simulateMs /= std::max(1, stepFrames);
  t.positionsInMs /= n, t.normalsMs /= n, t.planesMs /= n, t.tangentsMs /= n,
      t.meanRefittedPlaneFraction /= n;
  return t;
}

nlohmann::json distributionJson(const SampleSummary& s) {
  return {{"median", s.median}, {"p99", s.p99}, {"max", s.max}};
}

nlohmann::json framePathJson(const FramePathBench& b) {
  nlohmann::json out{{"mesh", b.mesh.string()},
                     {"frames", b.frames},
                     {"frame_time_s", b.frameTimeS},
                     {"move_tolerance_mm", b.moveToleranceMm},
                     {"integrators", nlohmann::json::array()}};
  for (const auto& t : b.integrators) {
    nlohmann::json r{{"integrator", sim::integratorName(t.integrator)},
                     {"substeps_per_frame", t.substepsPerFrame},
                     {"vertices", t.vertices},
                     {"springs", t.springs},
                     {"ms",
                      {{"simulate", t.simulateMs},
                       {"positions_in", t.positionsInMs},
                       {"normals", t.normalsMs},
                       {"planes_incremental", t.planesMs},
                       {"tangents", t.tangentsMs}}},
                     {"ms_total", t.totalMs()},
                     {"mean_refitted_plane_fraction", t.meanRefittedPlaneFraction}};
    if (t.integrator == sim::Integrator::FastMassSpring) r["factor_ms_once"] = t.factorMsOnce;
    out["integrators"].push_back(r);
  }
  return out;
}

nlohmann::json scenarioJson(const ScenarioBench& s) {
  nlohmann::json out{{"scenario", s.scenario.string()},
                     {"integrator", sim::integratorName(s.integrator)},
                     {"substeps", s.substeps},
                     {"frames", s.frames},
                     {"simulated_vertices", s.simulatedVertices},
                     {"springs", s.springs},
                     {"surface_vertices", s.surfaceVertices},
                     {"frame_ms", distributionJson(s.frameMs)},
                     {"substep_ms", distributionJson(s.substepMs)},
                     {"force_update_hz", s.forceUpdateHz},
                     {"divergence_events", s.divergenceEvents},
                     {"degraded_frames", s.degradedFrames},
                     {"max_force_N", s.maxForceN},
                     {"max_factor_ms", s.maxFactorMs},
                     {"explicit_limit_ms", s.explicitLimitMs}};
  if (s.refactorFrameMsMax) out["refactor_frame_ms_max"] = *s.refactorFrameMsMax;
  return out;
}

nlohmann::json timingJson(const IntegratorTiming& t) {
  nlohmann::json r{{"integrator", sim::integratorName(t.integrator)}, {"springs", t.springs}};
  if (!t.skipped.empty()) {
    r.update({{"ms_per_step", nullptr}, {"springs_per_second", nullptr}, {"skipped", t.skipped}});
    return r;
  }
  r.update({{"vertices", t.vertices},
            {"ms_per_step", t.msPerStep},
            {"springs_per_second", t.springsPerSecond()},
            {"h_s", t.stepS},
            {"substeps_per_frame", t.substepsPerFrame},
            {"ms_per_frame", t.msPerFrame()},
            {"ms_per_step_best", t.msPerStepBest},
            {"steps_timed", t.stepsTimed}});
  if (t.integrator == sim::Integrator::ImplicitEuler) r["cg_iterations_mean"] = t.cgIterationsMean;
  if (t.integrator == sim::Integrator::FastMassSpring)
    r.update({{"factor_ms_once", t.factorMsOnce}, {"local_global_iterations", t.localGlobalIterations}});
  return r;
}

/// One printf-formatted line of the text report.
__attribute__((format(printf, 1, 2))) std::string line(const char* format, ...) {
  char buffer[512];
  std::va_list args;
  va_start(args, format);
  std::vsnprintf(buffer, sizeof buffer, format, args);
  va_end(args);
  return buffer;
}

}  // namespace

Result<BenchPatch> makeBenchPatch(std::size_t targetSprings, int threads) {
  const int side = static_cast<int>(std::lround(std::sqrt(double(targetSprings) / 6.0))) + 1;
  std::vector<Float3> positions;
  std::vector<Triangle> triangles;
  for (int y = 0; y < side; ++y)
    for (int x = 0; x < side; ++x)
      positions.push_back({float(x), float(y), 0.0f});
  auto id = [side](int x, int y) { return static_cast<std::uint32_t>(y * side + x); };
  std::vector<std::uint32_t> pinned;
  for (int y = 0; y < side; ++y) {
    pinned.push_back(id(0, y));
    for (int x = 0; y + 1 < side && x + 1 < side; ++x) {
      triangles.push_back({id(x, y), id(x + 1, y), id(x + 1, y + 1)});
      triangles.push_back({id(x, y), id(x + 1, y + 1), id(x, y + 1)});
    }
  }
  auto springs = sim::buildSurfaceSprings(positions, triangles,
                                          {.stiffness = 0.1, .bendingStiffness = 0.02, .damping = 1e-6});
  if (!springs) return springs.error();
  auto masses = sim::computeMasses(positions, triangles, {.total = 0.0, .arealDensity = 1e-3});
  if (!masses) return masses.error();
  auto system = sim::makeSystem(std::move(*springs), std::move(*masses), pinned,
                                {.rayleighMass = 1.0, .threads = threads});
  if (!system) return system.error();
  return BenchPatch{std::move(*system), sim::restState(positions)};
}

double omegaBound(const sim::MassSpringSystem& system) {
  const sim::SpringNetwork& s = system.springs;
  std::vector<double> row(system.vertexCount(), 0.0);
  for (std::size_t e = 0; e < s.size(); ++e) {
    const double mi = system.masses[s.i[e]], mj = system.masses[s.j[e]];
    row[s.i[e]] += s.stiffness[e] * (1.0 / mi + 1.0 / std::sqrt(mi * mj));
    row[s.j[e]] += s.stiffness[e] * (1.0 / mj + 1.0 / std::sqrt(mi * mj));
  }
  return row.empty() ? 0.0 : std::sqrt(*std::max_element(row.begin(), row.end()));
}

IntegratorTiming timeIntegrator(sim::Integrator integrator, const BenchPatch& patch, double h,
                                const IntegratorBenchConfig& config) {
  sim::State state = patch.rest;
  sim::StepWorkspace ws;
  const sim::StepStats first = sim::step(integrator, patch.system, state, h, ws, config.solver);
  std::vector<double> times;
  long cg = 0;
  Stopwatch clock;
  while (int(times.size()) < config.maxTimedSteps && (times.empty() || clock.elapsedMs() < config.budgetMs)) {
    Stopwatch one;
    cg += sim::step(integrator, patch.system, state, h, ws, config.solver).cgIterations;
    times.push_back(one.elapsedMs());
  }
  IntegratorTiming r;
  r.integrator = integrator;
  r.springs = patch.system.springs.size();
  r.vertices = patch.system.vertexCount();
  r.stepS = h;
  r.stepsTimed = static_cast<int>(times.size());
  std::tie(r.msPerStep, r.msPerStepBest) = medianAndMin(times);
  r.substepsPerFrame = std::max(1, static_cast<int>(std::ceil(config.frameTimeS / h - 1e-9)));
  r.cgIterationsMean = double(cg) / r.stepsTimed;
  r.factorMsOnce = first.factorMs;
  r.localGlobalIterations = config.solver.localGlobalIterations;
  return r;
}

ForcePassTiming timeForcePass(BenchPatch& patch, int threads) {
  patch.system.config.threads = threads;
  std::vector<sim::Vec3d> forces(patch.system.vertexCount());
  sim::ForceScratch scratch;
  sim::computeForces(patch.system, patch.rest.x, patch.rest.v, forces, scratch);
  std::vector<double> times;
  Stopwatch clock;
  while (times.size() < 1000 && (times.size() < 5 || clock.elapsedMs() < 200.0)) {
    Stopwatch one;
    sim::computeForces(patch.system, patch.rest.x, patch.rest.v, forces, scratch);
    times.push_back(one.elapsedMs());
  }
  ForcePassTiming t;
  t.springs = patch.system.springs.size();
  t.threads = threads;
  std::tie(t.ms, t.msBest) = medianAndMin(times);
  return t;
}

Result<FramePathBench> benchFramePath(const std::filesystem::path& mesh, float sigmaTPerMm, int frames,
                                      int threads) {
  auto loaded = mesh::loadMesh(mesh, {.requireUvs = true});
  if (!loaded) return loaded.error();
  FramePathBench bench{.mesh = mesh, .frames = frames};
  for (sim::Integrator integrator :
       {sim::Integrator::SymplecticEuler, sim::Integrator::ImplicitEuler, sim::Integrator::FastMassSpring}) {
    auto t = timeFramePath(*loaded, integrator, sigmaTPerMm, bench, threads);
    if (!t) return t.error();
    bench.integrators.push_back(*t);
  }
  return bench;
}

Result<ScenarioBench> benchScenario(const std::filesystem::path& file, const scenario::ScenarioPaths& paths,
                                    int frames, std::optional<sim::Integrator> integrator) {
  auto parsed = scenario::loadScenario(file, paths);
  if (!parsed) return parsed.error();
  if (frames > 0) parsed->frames = frames;
  if (integrator) parsed->integrator = *integrator;
  auto run = scenario::ScenarioRun::create(*parsed);
  if (!run) return run.error();
  std::vector<double> total, perSubstep, graspFrames;
  ScenarioBench b{.scenario = file,
                  .integrator = parsed->integrator,
                  .substeps = parsed->substeps,
                  .frames = parsed->frames};
  long samples = 0;
  for (int f = 0; f < parsed->frames; ++f) {
    auto m = (*run)->advance();
    if (!m) return m.error();
    if (!m->finite) return Error{file.string() + ": frame " + std::to_string(f) + " holds NaN"};
    total.push_back(m->totalMs);
    perSubstep.push_back(m->totalMs / std::max(1, m->substeps));
    if (m->factorMs > 0.0 && m->grasped > 0) graspFrames.push_back(m->totalMs);
    samples += static_cast<long>(m->forceSamplesN.size());
    b.divergenceEvents += m->divergenceEvents;
    b.degradedFrames += m->degrade.empty() ? 0 : 1;
    b.maxForceN = std::max(b.maxForceN, m->forceMagnitudeN);
    b.maxFactorMs = std::max(b.maxFactorMs, m->factorMs);
  }
  const auto& system = (*run)->simulator().system();
  b.simulatedVertices = system.vertexCount();
  b.springs = system.springs.size();
  b.surfaceVertices = (*run)->mesh().positions.size();
  b.frameMs = summarizeSamples(total);
  b.substepMs = summarizeSamples(perSubstep);
  const double simulatedS = parsed->frames * parsed->frameTime;
  b.forceUpdateHz = simulatedS > 0.0 ? double(samples) / simulatedS : 0.0;
  if (!graspFrames.empty()) b.refactorFrameMsMax = summarizeSamples(graspFrames).max;
  b.explicitLimitMs = 2.0e3 / omegaBound(system);
  return b;
}

Result<SimBench> runSimBench(const SimBenchConfig& config) {
  SimBench bench{.threads = config.threads};
  Stopwatch total;
  const double frame = IntegratorBenchConfig{}.frameTimeS;
  for (std::size_t target :
       {std::size_t{1000}, std::size_t{10000}, std::size_t{100000}, std::size_t{1000000}}) {
    if (target > config.maxSprings) break;
    auto patch = makeBenchPatch(target, config.threads);
    if (!patch) return patch.error();
    const double explicitH = 0.9 * 2.0 / omegaBound(patch->system);
    for (sim::Integrator integrator :
         {sim::Integrator::ExplicitEuler, sim::Integrator::SymplecticEuler, sim::Integrator::VelocityVerlet,
          sim::Integrator::ImplicitEuler, sim::Integrator::FastMassSpring}) {
      const bool implicit =
          integrator == sim::Integrator::ImplicitEuler || integrator == sim::Integrator::FastMassSpring;
      if (integrator == sim::Integrator::FastMassSpring &&
          patch->system.springs.size() > config.fastSolverMaxSprings) {
        bench.results.push_back({.integrator = integrator,
                                 .springs = patch->system.springs.size(),
                                 .skipped = "factor too large for this machine (fill grows as n^1.5)"});
        continue;
      }
      bench.results.push_back(timeIntegrator(integrator, *patch, implicit ? frame : explicitH));
    }
    bench.forcePass.push_back(timeForcePass(*patch, 1));
    if (config.threads > 1) bench.forcePass.push_back(timeForcePass(*patch, config.threads));
  }
  if (!config.framePathMesh.empty()) {
    auto f = benchFramePath(config.framePathMesh, config.framePathSigmaTPerMm, config.framePathFrames,
                            config.threads);
    if (!f) return f.error();
    bench.framePath = std::move(*f);
  }
  if (!config.scenario.empty()) {
    auto s = benchScenario(config.scenario, config.scenarioPaths, config.scenarioFrames,
                           config.scenarioIntegrator);
    if (!s) return s.error();
    bench.scenario = std::move(*s);
  }
  bench.benchS = total.elapsedMs() * 1e-3;
  return bench;
}

std::string simBenchJson(const SimBench& bench) {
  nlohmann::json out{{"threads", bench.threads},
                     {"frame_time_s", IntegratorBenchConfig{}.frameTimeS},
                     {"bench_s", bench.benchS},
                     {"results", nlohmann::json::array()},
                     {"force_pass", nlohmann::json::array()}};
  out["model"] =
      "square patch, 1 mm spacing, edge springs 0.1 N/mm + bending 0.02 N/mm, damping 1e-6 N*s/mm, "
      "1e-3 g/mm^2, Rayleigh alpha 1/s, gravity, one edge pinned; explicit integrators at 0.9 of the "
      "Gershgorin bound 2/omega_max, implicit ones one step per 1/60 s frame; implicit Euler CG <= 100 "
      "iterations to 1e-6; fast-mass-spring 10 iterations";
  for (const auto& t : bench.results)
    out["results"].push_back(timingJson(t));
  for (const auto& t : bench.forcePass)
    out["force_pass"].push_back({{"springs", t.springs},
                                 {"threads", t.threads},
                                 {"ms", t.ms},
                                 {"ms_best", t.msBest},
                                 {"springs_per_second", t.springsPerSecond()},
                                 {"springs_per_second_best", t.springsPerSecondBest()}});
  if (bench.framePath) out["frame_path"] = framePathJson(*bench.framePath);
  if (bench.scenario) out["scenario"] = scenarioJson(*bench.scenario);
  return detail::jsonText(out);
}

std::string simBenchText(const SimBench& bench) {
  std::string out = line("%-18s %9s %11s %12s %9s %12s\n", "integrator", "springs", "ms/step", "Msprings/s",
                         "substeps", "ms/frame");
  for (const auto& t : bench.results) {
    const std::string name(sim::integratorName(t.integrator));
    out += t.skipped.empty()
               ? line("%-18s %9zu %11.4f %12.2f %9d %12.3f\n", name.c_str(), t.springs, t.msPerStep,
                      t.springsPerSecond() * 1e-6, t.substepsPerFrame, t.msPerFrame())
               : line("%-18s %9zu  skipped: %s\n", name.c_str(), t.springs, t.skipped.c_str());
  }
  out += line("\nforce pass (median; best):\n%9s %8s %10s %12s %12s\n", "springs", "threads", "ms",
              "Msprings/s", "best");
  for (const auto& t : bench.forcePass)
    out += line("%9zu %8d %10.4f %12.2f %12.2f\n", t.springs, t.threads, t.ms, t.springsPerSecond() * 1e-6,
                t.springsPerSecondBest() * 1e-6);
  if (bench.framePath) out += "\nframe path:\n" + framePathJson(*bench.framePath).dump(2) + "\n";
  if (const auto& s = bench.scenario) {
    out += line("\nscenario %s (%s, %d substeps, %zu nodes, %zu springs, %d frames):\n", s->scenario.c_str(),
                std::string(sim::integratorName(s->integrator)).c_str(), s->substeps, s->simulatedVertices,
                s->springs, s->frames);
    out += line("  ms per frame  median %.3f  p99 %.3f  max %.3f\n", s->frameMs.median, s->frameMs.p99,
                s->frameMs.max);
    out += line("  ms per substep median %.4f  p99 %.4f  max %.4f\n", s->substepMs.median, s->substepMs.p99,
                s->substepMs.max);
    out += line(
        "  force updates %.0f Hz   divergence events %ld   degraded frames %ld   max force %.3f N   "
        "max refactor %.3f ms\n",
        s->forceUpdateHz, s->divergenceEvents, s->degradedFrames, s->maxForceN, s->maxFactorMs);
  }
  return out;
}

}  // namespace tissue::studies
