// Simulation stress (issue 14, item 4): 1000 randomised cases on small patches - stiffness x
// 10^-3..10^3, frame time x 0.1..10, every integrator, pins, gravity, a live tool that jerks and
// teleports, changes radius, grasps (sometimes everything) and releases. Asserted every frame:
// the positions handed on (as doubles and as the floats the mesh module and renderer receive) are
// finite; a frame that reports no divergence holds no over-stretched spring (nothing diverged
// unreported); a frame's work stays within Simulator::frameWorkBound() (steps, solver iterations)
// and the tool's sub-moves within substeps x maxSubMoves. Work is counted, not timed; the wall
// times are printed only (docs/RESULTS.md).
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>

#include "test_systems.h"
#include "tissue/sim/forces.h"
#include "tissue/sim/instrument.h"
#include "tissue/sim/simulator.h"

namespace tissue::sim {
namespace {

struct StressFigures {
  long cases = 0, frames = 0, divergentFrames = 0, events = 0, relaxedFrames = 0, teleports = 0;
  int worstSteps = 0, worstIterations = 0, worstSubMoves = 0;
  double worstMs = 0.0;
};

// The base case: a 10 mm patch of 1 g at k = 0.05 N/mm, 60 Hz frames (the tests' membrane).
constexpr double kBaseStiffness = 0.05;  // N/mm
constexpr double kBaseFrameTime = 1.0 / 60.0;

class Case {
 public:
  explicit Case(std::mt19937_64& rng) : m_rng(rng) {}

  // Runs one case; false (with gtest failures) as soon as a property fails.
  bool run(StressFigures& fig) {
    const int nx = pick(3, 9), ny = pick(3, 9);
    const float spacing = static_cast<float>(uniform(0.5, 3.0));
    const auto patch = test::gridPatch(nx, ny, spacing);
    const double stiffness = kBaseStiffness * std::pow(10.0, uniform(-3.0, 3.0));
    std::vector<std::uint32_t> pinned;
    const int pinMode = pick(0, 3);  // none, a corner, a row, random
    for (int k = 0; k < nx * ny; ++k)
      if ((pinMode == 1 && k == 0) || (pinMode == 2 && k < nx) || (pinMode == 3 && uniform(0, 1) < 0.2))
        pinned.push_back(static_cast<std::uint32_t>(k));
    SystemConfig sys{.gravity = uniform(0, 1) < 0.7 ? Vec3d{0.0, 0.0, -9806.65} : Vec3d{},
                     .rayleighMass = uniform(0, 1) < 0.5 ? uniform(0.0, 10.0) : 0.0,
                     .rayleighStiffness = 0.0,
                     .threads = 1};
    auto system =
        test::patchSystem(patch, stiffness, uniform(0.0, 1e-3) * stiffness, uniform(0.1, 10.0), pinned, sys);
    SimulatorConfig config{.integrator = static_cast<Integrator>(pick(0, 4)),
                           .frameTime = kBaseFrameTime * std::pow(10.0, uniform(-1.0, 1.0)),
                           .substeps = pick(1, 8)};
    config.solver.maxIterations = pick(5, 200);
    config.solver.relativeTolerance = std::pow(10.0, uniform(-10.0, -3.0));
    config.solver.localGlobalIterations = pick(1, 20);
    config.recovery.frameBudgetMs = 0.0;  // no wall-clock cut: the work bound must hold by itself
    auto sim = Simulator::create(std::move(system), restState(patch.positions), config);
    EXPECT_TRUE(sim.ok()) << (sim.ok() ? "" : sim.error().message);
    if (!sim.ok()) return false;

    const double side = static_cast<double>(spacing);
    const Vec3d centre{0.5 * (nx - 1) * side, 0.5 * (ny - 1) * side, 0.0};
    InstrumentConfig toolConfig{.shape = {pick(0, 1) ? ToolShapeKind::Capsule : ToolShapeKind::Sphere,
                                          uniform(0.5, 5.0), uniform(0.0, 10.0)}};
    if (uniform(0, 1) < 0.2) toolConfig.graspMarginMm = 1e6;  // grasp everything
    auto tool = Instrument::createLive(toolConfig, {centre + Vec3d{0.0, 0.0, -uniform(1.0, 10.0)}});
    EXPECT_TRUE(tool.ok()) << (tool.ok() ? "" : tool.error().message);
    if (!tool.ok()) return false;
    sim->setSubstepHook(&*tool);
    const FrameWorkBound bound = sim->frameWorkBound();

    const int frames = pick(5, 20);
    for (int f = 0; f < frames; ++f) {
      if (!act(*sim, *tool, centre)) return false;
      const auto start = std::chrono::steady_clock::now();
      const FrameReport report = sim->advanceFrame();
      const double ms =
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
      const InstrumentFrameReport toolReport = tool->lastFrame();
      if (!check(*sim, report, toolReport, bound, config, f)) return false;
      ++fig.frames;
      fig.events += static_cast<long>(report.events.size());
      if (!report.events.empty()) ++fig.divergentFrames;
      if (report.degrade == "relaxed") ++fig.relaxedFrames;
      fig.teleports += toolReport.teleports;
      fig.worstSteps = std::max(fig.worstSteps, report.stepsRun);
      fig.worstIterations = std::max(fig.worstIterations, report.solverIterations);
      fig.worstSubMoves = std::max(fig.worstSubMoves, toolReport.subMoves);
      fig.worstMs = std::max(fig.worstMs, ms);
    }
    ++fig.cases;
    return true;
  }

 private:
  int pick(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(m_rng); }
  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(m_rng); }

  // The tool's input for the next frame: a small move, a jerk, a teleport, a new radius, a grasp
  // or a release.
  bool act(Simulator& sim, Instrument& tool, const Vec3d& centre) {
    const double r = uniform(0, 1);
    const Vec3d dir = normalizedOr(Vec3d{uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)}, {0.0, 0.0, 1.0});
    if (r < 0.5) {
      tool.setTarget({tool.pose().position + uniform(0.0, 2.0) * dir, dir});
    } else if (r < 0.65) {
      tool.setTarget({centre + uniform(5.0, 50.0) * dir, dir});  // a jerk: tens of mm in one frame
    } else if (r < 0.72) {
      tool.setTarget({centre + std::pow(10.0, uniform(3.0, 7.0)) * dir, dir});  // a teleport: 1 m..10 km
    } else if (r < 0.77) {
      tool.setTarget({centre, dir});  // back onto the tissue
    } else if (r < 0.82) {
      auto ok = tool.setRadius(uniform(0.2, 8.0));
      EXPECT_TRUE(ok.ok());
    } else if (r < 0.92) {
      auto taken = tool.grasp(sim);
      EXPECT_TRUE(taken.ok()) << (taken.ok() ? "" : taken.error().message);
      if (!taken.ok()) return false;
    } else {
      auto ok = tool.release(sim);
      EXPECT_TRUE(ok.ok());
    }
    return true;
  }

  static bool check(const Simulator& sim, const FrameReport& report, const InstrumentFrameReport& tool,
                    const FrameWorkBound& bound, const SimulatorConfig& config, int frame) {
    const State& s = sim.state();
    for (std::size_t k = 0; k < s.x.size(); ++k) {
      EXPECT_TRUE(isFinite(s.x[k]) && isFinite(s.v[k])) << "frame " << frame << " vertex " << k;
      if (!isFinite(s.x[k]) || !isFinite(s.v[k])) return false;
    }
    for (const Float3& p : toFloat3(s.x)) {  // what the mesh module and the renderer receive
      const bool finite = std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
      EXPECT_TRUE(finite) << "frame " << frame << ": a float position overflowed";
      if (!finite) return false;
    }
    // A divergence that reached the state unreported: an over-stretched spring in a quiet frame.
    if (report.events.empty()) {
      const double stretch = maxStretch(sim.system(), s.x);
      EXPECT_LE(stretch, config.limits.maxStretch) << "frame " << frame << ": unreported divergence";
      if (!(stretch <= config.limits.maxStretch)) return false;
    } else {
      EXPECT_FALSE(report.degrade.empty()) << "frame " << frame << ": events without a degrade";
      for (const DivergenceEvent& e : report.events)
        EXPECT_FALSE(e.reason.empty() || e.action.empty()) << "frame " << frame;
    }
    EXPECT_LE(report.events.size(), 2u) << "frame " << frame;
    EXPECT_LE(report.stepsRun, bound.steps) << "frame " << frame;
    EXPECT_LE(report.solverIterations, bound.solverIterations) << "frame " << frame;
    EXPECT_LE(tool.subMoves, config.substeps * 64) << "frame " << frame;  // InstrumentConfig::maxSubMoves
    return report.events.size() <= 2u && report.stepsRun <= bound.steps &&
           report.solverIterations <= bound.solverIterations && tool.subMoves <= config.substeps * 64;
  }

  std::mt19937_64& m_rng;
};

TEST(SimulationStress, ThousandRandomisedCasesHandOnFiniteStatesReportDivergencesAndStayBounded) {
  std::mt19937_64 rng(20261202);  // fixed seed: the same 1000 cases every run
  StressFigures fig;
  const auto start = std::chrono::steady_clock::now();
  for (int c = 0; c < 1000; ++c) {
    Case one(rng);
    ASSERT_TRUE(one.run(fig)) << "case " << c;
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf(
      "stress: %ld cases, %ld frames, %ld divergent frames (%ld events, %ld relaxed), %ld teleport "
      "substeps;\n"
      "        worst frame: %d steps, %d solver iterations, %d tool sub-moves, %.2f ms; total %.1f s\n",
      fig.cases, fig.frames, fig.divergentFrames, fig.events, fig.relaxedFrames, fig.teleports,
      fig.worstSteps, fig.worstIterations, fig.worstSubMoves, fig.worstMs, seconds);
  EXPECT_EQ(fig.cases, 1000);
  // The ranges reach far past every integrator's limit: divergences must occur, and be reported.
  EXPECT_GT(fig.divergentFrames, 0);
  EXPECT_GT(fig.teleports, 0);
}

}  // namespace
}  // namespace tissue::sim
