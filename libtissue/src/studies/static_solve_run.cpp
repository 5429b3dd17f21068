// A scenario's static equilibrium (static_solve_run.h).
#include "tissue/studies/static_solve_run.h"

#include <algorithm>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <numeric>

#include "tissue/core/stopwatch.h"
#include "tissue/sim/lattice.h"
#include "tissue/sim/system.h"

namespace tissue::studies {
namespace {

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

}  // namespace

Result<StaticSolution> solveScenarioStatic(const scenario::Scenario& scenario,
                                           const sim::StaticSolveConfig& config) {
  auto mesh = scenario::loadScenarioMesh(scenario);
  if (!mesh) return mesh.error();
  auto system = scenario::buildSystem(scenario, *mesh);
  if (!system) return system.error();

  Stopwatch clock;
  // A lattice scenario simulates the lattice nodes; the surface follows by the embedding.
  std::vector<sim::Vec3d> x = sim::restState(mesh->simulatedRestPositions()).x;
  StaticSolution s;
  s.report = sim::solveStatic(*system, x, config);
  s.ms = clock.elapsedMs();
  std::vector<sim::Vec3d> surface = x;
  if (mesh->lattice) {
    std::vector<Float3> embedded(mesh->positions.size());
    sim::embedPositions(*mesh->lattice, x, embedded);
    surface = sim::restState(embedded).x;
  }
  s.vertices = surface.size();
  s.positionLines = positionLines(surface, mesh->fileIndex);
  s.json = nlohmann::json{
      {"vertices", s.vertices},
      {"converged", s.report.converged},
      {"iterations", s.report.iterations},
      {"accepted_steps", s.report.acceptedSteps},
      {"residual_N", s.report.residualN},
      {"tolerance_N", config.toleranceN},
      {"ms",
       s.ms}}.dump();
  return s;
}

}  // namespace tissue::studies
