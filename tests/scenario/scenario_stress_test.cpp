// Simulation stress on the data liver (issue 14, item 4; the small-mesh 1000 cases are in
// tests/sim/stress_test.cpp): randomised scenarios of the embedded-lattice liver - stiffness x
// 10^-3..10^3 of the main scenario's, dt x 0.1..10, every integrator, a path with jerks and a
// teleport, grasps (sometimes of everything) and releases. Asserted every frame: the surface
// positions handed to the mesh module and the renderer (ScenarioRun::positions) are finite; a
// frame without a divergence event holds no over-stretched spring; the work stays within
// frameWorkBound(). Labelled "slow" (seconds per case).
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <sstream>

#include "tissue/scenario/scenario_run.h"

namespace tissue::scenario {
namespace {

std::string randomScenario(std::mt19937_64& rng) {
  auto uniform = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
  auto pick = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
  const char* integrators[] = {"explicit-euler", "symplectic-euler", "verlet", "implicit-euler",
                               "fast-mass-spring"};
  std::ostringstream s;
  s.precision(17);
  s << R"({"mesh": ")" << TISSUE_TEST_DATA_DIR << R"(/meshes/liver.obj",)"
    << R"("springs": {"from": "lattice", "stiffness": )" << 0.018 * std::pow(10.0, uniform(-3.0, 3.0)) << "},"
    << R"("lattice": {"cell_size": 12}, "mass": {"density": 0.00106},)"
    << R"("damping": {"springs": 0.00002, "rayleigh_mass": 5.0}, "gravity": [0, 0, -9806.65],)"
    << R"("pinned": {"axis": "z", "below": -13}, "integrator": ")" << integrators[pick(0, 4)] << R"(",)"
    << R"("dt": )" << std::pow(10.0, uniform(-1.0, 1.0)) / 60.0 << R"(, "substeps": )" << pick(1, 17)
    << R"(, "frames": 30, "solver": {"max_iterations": )" << pick(5, 50) << R"(, "tolerance": 1e-3},)"
    << R"("instrument": {"shape": "sphere", "radius": )" << uniform(2.0, 12.0) << R"(, "grasp_margin": )"
    << (pick(0, 3) == 0 ? 1e4 : 2.0) << R"(, "path": [)";
  // Keyframes 0.05..0.2 s apart: onto the top, jerks of tens of mm, one teleport of 1..100 m.
  double t = 0.0;
  const int teleportAt = pick(2, 6);
  for (int k = 0; k < 8; ++k) {
    const double scale = k == teleportAt ? std::pow(10.0, uniform(3.0, 5.0)) : uniform(0.0, 40.0);
    s << (k ? "," : "") << R"({"time": )" << t << R"(, "position": [)" << 31.82 + scale * uniform(-1, 1)
      << ", " << scale * uniform(-1, 1) << ", " << 50.0 + scale * uniform(-1, 1) << "]}";
    t += uniform(0.05, 0.2);
  }
  s << R"(], "actions": [{"time": )" << uniform(0.0, 0.5) << R"(, "action": "grasp"}, {"time": )"
    << uniform(0.5, 1.0) << R"(, "action": "release"}]}})";
  return s.str();
}

TEST(ScenarioStress, RandomisedLiverScenariosHandOnFiniteSurfacesWithinTheWorkBound) {
  std::mt19937_64 rng(1402);
  long frames = 0, divergentFrames = 0, events = 0, teleports = 0;
  int worstSteps = 0, worstIterations = 0;
  double worstMs = 0.0;
  constexpr int kCases = 20;
  for (int c = 0; c < kCases; ++c) {
    const std::string text = randomScenario(rng);
    auto s = parseScenario(text, "stress.json");
    ASSERT_TRUE(s.ok()) << s.error().message << "\n" << text;
    auto run = ScenarioRun::create(*s);
    ASSERT_TRUE(run.ok()) << run.error().message;
    const sim::FrameWorkBound bound = (*run)->frameWorkBound();
    for (int f = 0; f < s->frames; ++f) {
      const auto start = std::chrono::steady_clock::now();
      auto m = (*run)->advance();
      const double ms =
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
      ASSERT_TRUE(m.ok()) << m.error().message;
      ASSERT_TRUE(m->finite) << "case " << c << " frame " << f;
      for (const Float3& p : (*run)->positions())
        ASSERT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z))
            << "case " << c << " frame " << f;
      if (m->divergenceEvents == 0) {
        ASSERT_LE(m->maxStretch, sim::DivergenceLimits{}.maxStretch) << "case " << c << " frame " << f;
      } else {
        ASSERT_FALSE(m->divergenceReason.empty() || m->degrade.empty()) << "case " << c << " frame " << f;
      }
      ASSERT_LE(m->divergenceEvents, 2);
      ASSERT_LE(m->stepsRun, bound.steps);
      ASSERT_LE(m->solverIterations, bound.solverIterations);
      ASSERT_LE(m->toolSubMoves, s->substeps * sim::InstrumentConfig{}.maxSubMoves);
      ++frames;
      events += m->divergenceEvents;
      divergentFrames += m->divergenceEvents > 0;
      teleports += m->teleports;
      worstSteps = std::max(worstSteps, m->stepsRun);
      worstIterations = std::max(worstIterations, m->solverIterations);
      worstMs = std::max(worstMs, ms);
    }
  }
  std::printf(
      "liver stress: %d cases, %ld frames, %ld divergent frames (%ld events), %ld teleport substeps;\n"
      "              worst frame: %d steps, %d solver iterations, %.1f ms\n",
      kCases, frames, divergentFrames, events, teleports, worstSteps, worstIterations, worstMs);
  EXPECT_EQ(frames, kCases * 30L);
}

}  // namespace
}  // namespace tissue::scenario
