#include "poke_to_rest.h"

#include <algorithm>
#include <cmath>

#include "tissue/sim/simulator.h"
#include "tissue/sim/units.h"

namespace tissue::sim::test {

PokeSetup makePokeSetup(const std::vector<Float3>& positions, double pinFraction, double pokeRadius) {
  PokeSetup setup;
  float ymin = positions[0].y, ymax = positions[0].y;
  std::size_t top = 0;
  for (std::size_t v = 0; v < positions.size(); ++v) {
    ymin = std::min(ymin, positions[v].y);
    if (positions[v].y > ymax) ymax = positions[v].y, top = v;
  }
  const double cut = double{ymin} + pinFraction * (double{ymax} - double{ymin});
  const Vec3d t{positions[top].x, positions[top].y, positions[top].z};
  for (std::size_t v = 0; v < positions.size(); ++v) {
    const Vec3d p{positions[v].x, positions[v].y, positions[v].z};
    if (p.y < cut) setup.pinned.push_back(static_cast<std::uint32_t>(v));
    if (length(p - t) <= pokeRadius) setup.poked.push_back(static_cast<std::uint32_t>(v));
  }
  return setup;
}

RestResult solveToRest(SpringNetwork springs, std::vector<double> masses, const std::vector<Vec3d>& rest,
                       const std::vector<std::uint32_t>& pinned, const std::vector<Vec3d>& forces,
                       int maxFrames, double moveTolerance) {
  // Constant forces as long pre-stretched springs to pinned anchors (see the header).
  const double stretch = 1e5;  // mm, = rest length of the anchor springs
  const std::size_t n = rest.size();
  State state{rest, std::vector<Vec3d>(n)};
  std::vector<std::uint32_t> pins = pinned;
  for (std::size_t v = 0; v < n; ++v) {
    const double f = length(forces[v]);
    if (!(f > 0.0)) continue;
    const Vec3d dir = (1.0 / f) * forces[v];
    const auto anchor = static_cast<std::uint32_t>(state.x.size());
    state.x.push_back(rest[v] + (2.0 * stretch) * dir);
    state.v.push_back({});
    masses.push_back(1.0);
    pins.push_back(anchor);
    // k * stretch = f, with k given in N/mm.
    addSpring(springs, static_cast<std::uint32_t>(v), anchor, stretch, f / stretch / kStiffnessPerNewtonPerMm,
              0.0);
  }
  RestResult result;
  if (!finalizeSpringNetwork(springs, state.x.size())) return result;
  SystemConfig config{.gravity = {0, 0, 0}, .rayleighMass = 5.0};
  auto system = makeSystem(std::move(springs), std::move(masses), pins, config);
  if (!system) return result;
  SimulatorConfig sim{.integrator = Integrator::ImplicitEuler, .frameTime = 0.05};
  sim.solver.maxIterations = 400;
  auto simulator = Simulator::create(std::move(*system), std::move(state), sim);
  if (!simulator) return result;
  std::vector<Vec3d> previous = simulator->state().x;
  for (result.frames = 1; result.frames <= maxFrames; ++result.frames) {
    simulator->advanceFrame();
    double largest = 0.0;
    for (std::size_t v = 0; v < n; ++v)
      largest = std::max(largest, length(simulator->state().x[v] - previous[v]));
    previous = simulator->state().x;
    if (largest < moveTolerance) {
      result.converged = true;
      break;
    }
  }
  result.x.assign(previous.begin(), previous.begin() + static_cast<long>(n));
  return result;
}

}  // namespace tissue::sim::test
