// tissue-sim sim-bench, the frame path: the data organ as a spring network, poked and released;
// per frame one simulation step, then DeformableSurface::update (positions in, normals,
// incremental plane re-fit, tangent rebuild), each timed.
#include <algorithm>
#include <cmath>

#include "organ_data.h"
#include "sim_bench.h"
#include "tissue/core/stopwatch.h"
#include "tissue/mesh/deformable_surface.h"
#include "tissue/mesh/load_mesh.h"
#include "tissue/mesh/vertex_normals.h"
#include "tissue/sim/integrators.h"
#include "tissue/sim/mass.h"
#include "tissue/sim/spring_network.h"
#include "tissue/studies/deformations.h"
#include "tissue/studies/sim_bench.h"

namespace tissue::sim_app {
namespace {

constexpr double kFrameTime = 1.0 / 60.0;  ///< s
constexpr float kPokeDepth = 8.0f;         ///< mm, the released indentation
constexpr double kPokeFraction = 0.05;     ///< of the vertices
constexpr float kMoveTolerance = 1e-3f;    ///< mm: vertices that move less keep their planes

/// The organ's springs (0.1 N/mm edges, 0.02 N/mm bending, 1e-5 N*s/mm damping), masses
/// (0.0106 g/mm^2: a 10 mm shell of 1.06 g/cm^3 tissue), the lowest 10% (z) pinned as if the
/// organ rested on a support, no gravity (the support carries it), Rayleigh alpha 2 /s.
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
  std::vector<std::uint32_t> pinned;
  for (std::size_t v = 0; v < rest.size(); ++v)
    if (rest[v].z < zMin + 0.1f * (zMax - zMin)) pinned.push_back(static_cast<std::uint32_t>(v));
  return sim::makeSystem(std::move(*springs), std::move(*masses), pinned,
                         {.gravity = {}, .rayleighMass = 2.0, .threads = threads});
}

}  // namespace

Result<nlohmann::json> measureFramePath(const FramePathOptions& o) {
  auto loaded = mesh::loadMesh(o.mesh, {.requireUvs = true});
  if (!loaded) return loaded.error();
  auto material = readDataMaterial(materialFileFor(o.mesh));
  const float sigmaT = material ? scene::firstLayerMinSigmaT(*material) : 1.5f;
  nlohmann::json out;
  out["mesh"] = o.mesh.string();
  out["frames"] = o.frames;
  out["frame_time_s"] = kFrameTime;
  out["move_tolerance_mm"] = kMoveTolerance;
  out["integrators"] = nlohmann::json::array();
  for (sim::Integrator integrator :
       {sim::Integrator::SymplecticEuler, sim::Integrator::ImplicitEuler, sim::Integrator::FastMassSpring}) {
    auto surface = mesh::DeformableSurface::create(*loaded, {.sigma_t = sigmaT, .epsilon = 0.01f},
                                                   static_cast<unsigned>(o.threads));
    if (!surface) return surface.error();
    const auto rest = surface->geometricRestPositions();
    auto system = organSystem(rest, surface->geometricTriangles(), o.threads);
    if (!system) return system.error();

    // Released from a poke: the top 5% pushed in 8 mm, then let go.
    std::vector<Float3> normals(rest.size()), poked(rest.size());
    mesh::computeVertexNormals(rest, surface->geometricTriangles(), normals);
    studies::applyPoke(rest, normals, studies::topVertex(rest), kPokeFraction, kPokeDepth, poked);
    sim::State state = sim::restState(poked);
    for (std::size_t v = 0; v < rest.size(); ++v)
      if (system->invMasses[v] == 0.0) state.x[v] = {rest[v].x, rest[v].y, rest[v].z};
    sim::StepWorkspace ws;
    const sim::ImplicitSolverConfig solver{.maxIterations = 100, .relativeTolerance = 1e-6};
    (void)surface->update(sim::toFloat3(state.x));
    // Explicit: substeps at 0.9 of the stability bound 2/omega_max; implicit: one step a frame.
    const int substeps =
        integrator == sim::Integrator::SymplecticEuler
            ? static_cast<int>(std::ceil(kFrameTime / (0.9 * 2.0 / studies::omegaBound(*system))))
            : 1;

    double stepMs = 0, gatherMs = 0, normalsMs = 0, planesMs = 0, tangentsMs = 0, refitted = 0, factorMs = 0;
    int stepFrames = 0;
    for (int f = 0; f < o.frames; ++f) {
      Stopwatch clock;
      sim::StepStats stats;
      for (int k = 0; k < substeps; ++k)
        stats = sim::step(integrator, *system, state, kFrameTime / substeps, ws, solver);
      const std::vector<Float3> positions = sim::toFloat3(state.x);
      if (stats.refactored) {
        factorMs = stats.factorMs;  // the one-off factorisation is reported on its own
      } else {
        stepMs += clock.elapsedMs();
        ++stepFrames;
      }
      const auto update = surface->update(positions, kMoveTolerance);
      gatherMs += update.gatherMs, normalsMs += update.normalsMs, planesMs += update.planesMs,
          tangentsMs += update.tangentsMs;
      refitted += double(update.refit.refittedPlanes) / double(rest.size());
    }
    const double n = o.frames;
    stepFrames = std::max(1, stepFrames);
    nlohmann::json r;
    r["integrator"] = sim::integratorName(integrator);
    r["substeps_per_frame"] = substeps;
    r["vertices"] = rest.size();
    r["springs"] = system->springs.size();
    r["ms"] = {{"simulate", stepMs / stepFrames},
               {"positions_in", gatherMs / n},
               {"normals", normalsMs / n},
               {"planes_incremental", planesMs / n},
               {"tangents", tangentsMs / n}};
    r["ms_total"] = stepMs / stepFrames + (gatherMs + normalsMs + planesMs + tangentsMs) / n;
    r["mean_refitted_plane_fraction"] = refitted / n;
    if (integrator == sim::Integrator::FastMassSpring) r["factor_ms_once"] = factorMs;
    out["integrators"].push_back(r);
  }
  return out;
}

}  // namespace tissue::sim_app
