// Divergence: detected within the frame, rolled back, recovered, reported; never NaN out.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "test_systems.h"
#include "tissue/sim/simulator.h"

namespace tissue::sim {
namespace {

bool allFinite(const State& s) {
  for (std::size_t k = 0; k < s.x.size(); ++k)
    if (!isFinite(s.x[k]) || !isFinite(s.v[k])) return false;
  return true;
}

State displacedSpring() {
  return {{{}, {11.0, 0.0, 0.0}}, {{}, {}}};
}

TEST(Divergence, ExplicitEulerPastTheLimitDegradesWithOneRetryPerFrameAtMost) {
  // m = 1 g, k = 0.1 N/mm: the limit 2 sqrt(m/k) is 6.3 ms; frames of 20 ms in one step.
  SimulatorConfig config{.integrator = Integrator::ExplicitEuler, .frameTime = 0.02, .substeps = 1};
  config.recovery.relaxAfterFrames = 0;  // keep the fallback
  auto sim = Simulator::create(test::oneSpring(1.0, 0.1), displacedSpring(), config);
  ASSERT_TRUE(sim.ok()) << sim.error().message;
  std::vector<DivergenceEvent> events;
  for (int f = 0; f < 200; ++f) {
    const FrameReport report = sim->advanceFrame();
    // Bounded: at most one retry (with the next more stable integrator), then relax.
    ASSERT_LE(report.events.size(), 2u) << "frame " << f;
    for (const auto& e : report.events) {
      EXPECT_EQ(e.nextSubsteps, e.substeps);  // never more substeps
      EXPECT_EQ(e.substeps, 1);
    }
    if (report.events.size() == 2) {
      EXPECT_FALSE(report.events.back().recovered);
      EXPECT_EQ(report.degrade, "relaxed");
    }
    events.insert(events.end(), report.events.begin(), report.events.end());
    ASSERT_TRUE(allFinite(sim->state())) << "frame " << f;
    ASSERT_LE(maxStretch(sim->system(), sim->state().x), config.limits.maxStretch) << "frame " << f;
  }
  ASSERT_FALSE(events.empty());
  EXPECT_EQ(events.front().integrator, Integrator::ExplicitEuler);
  EXPECT_EQ(events.front().nextIntegrator, Integrator::SymplecticEuler);
  // Explicit Euler gains energy at every h, symplectic Euler at this h: it ends on implicit Euler.
  EXPECT_EQ(sim->integrator(), Integrator::ImplicitEuler);
  EXPECT_LT(maxStretch(sim->system(), sim->state().x), 2.0);
}

TEST(Divergence, SymplecticEulerPastTheLimitFallsBackToImplicitEulerAtTheSameSubsteps) {
  SimulatorConfig config{.integrator = Integrator::SymplecticEuler, .frameTime = 0.02, .substeps = 1};
  auto sim = Simulator::create(test::oneSpring(1.0, 0.1), displacedSpring(), config);
  ASSERT_TRUE(sim.ok());
  const FrameReport first = sim->advanceFrame();
  ASSERT_EQ(first.events.size(), 1u);
  EXPECT_TRUE(first.events[0].recovered);
  EXPECT_EQ(first.events[0].action, "retry with implicit-euler");
  EXPECT_EQ(first.degrade, "fallback implicit-euler");
  EXPECT_EQ(first.integrator, Integrator::ImplicitEuler);
  EXPECT_GT(first.recoveryMs, 0.0);
  for (int f = 0; f < 50; ++f) {
    const FrameReport report = sim->advanceFrame();
    ASSERT_LE(report.events.size(), 1u);  // the retry always succeeds: never relaxed
    ASSERT_EQ(report.substeps, 1);
    ASSERT_TRUE(allFinite(sim->state()));
  }
}

TEST(Divergence, FallbackIntegratorIsReplacedBackAfterQuietFrames) {
  // After 5 quiet frames on implicit Euler the simulator tries symplectic Euler again, which
  // diverges once and falls back again: revisited, never kept for good, never left unstable.
  SimulatorConfig config{.integrator = Integrator::SymplecticEuler, .frameTime = 0.02, .substeps = 1};
  config.recovery.relaxAfterFrames = 5;
  auto sim = Simulator::create(test::oneSpring(1.0, 0.1), displacedSpring(), config);
  ASSERT_TRUE(sim.ok());
  EXPECT_FALSE(sim->advanceFrame().events.empty());
  ASSERT_EQ(sim->integrator(), Integrator::ImplicitEuler);
  int events = 0, symplecticFrames = 0;
  for (int f = 0; f < 30; ++f) {
    if (sim->integrator() == Integrator::SymplecticEuler) ++symplecticFrames;
    const FrameReport report = sim->advanceFrame();
    events += static_cast<int>(report.events.size());
    ASSERT_TRUE(allFinite(sim->state()));
    for (const auto& e : report.events)
      EXPECT_TRUE(e.recovered);
  }
  EXPECT_GT(symplecticFrames, 0);  // it went back
  EXPECT_GT(events, 0);            // and fell back again
}

TEST(Divergence, NoTimeLeftRelaxesTheFrameToItsStartAtRest) {
  // A frame budget already spent: no retry, the frame keeps its start positions, at rest.
  SimulatorConfig config{.integrator = Integrator::ExplicitEuler, .frameTime = 0.02, .substeps = 1};
  config.recovery.frameBudgetMs = 1e-12;
  auto sim = Simulator::create(test::oneSpring(1.0, 0.1), displacedSpring(), config);
  ASSERT_TRUE(sim.ok());
  const State start = sim->state();
  FrameReport report;
  for (int f = 0; f < 20 && report.events.empty(); ++f)
    report = sim->advanceFrame();
  ASSERT_EQ(report.events.size(), 1u);
  EXPECT_FALSE(report.events[0].recovered);
  EXPECT_EQ(report.events[0].action, "relaxed to rest");
  EXPECT_EQ(report.degrade, "relaxed");
  for (const Vec3d& v : sim->state().v)
    EXPECT_EQ(v, Vec3d{});
  EXPECT_TRUE(allFinite(sim->state()));
  (void)start;
}

TEST(Divergence, ImplicitEulerAndTheFastSolverAtTheSameStepHaveNoEvent) {
  for (Integrator integrator : {Integrator::ImplicitEuler, Integrator::FastMassSpring}) {
    SimulatorConfig config{.integrator = integrator, .frameTime = 0.02, .substeps = 1};
    auto sim = Simulator::create(test::oneSpring(1.0, 0.1), displacedSpring(), config);
    ASSERT_TRUE(sim.ok());
    for (int f = 0; f < 50; ++f)
      EXPECT_TRUE(sim->advanceFrame().events.empty()) << integratorName(integrator) << " frame " << f;
    EXPECT_EQ(sim->integrator(), integrator);
    EXPECT_LT(std::abs(sim->state().x[1].x - 10.0), 1.0);  // damped towards rest, never away
  }
}

TEST(Divergence, BadStateIsRejected) {
  State nan = displacedSpring();
  nan.x[1].x = std::nan("");
  EXPECT_FALSE(Simulator::create(test::oneSpring(1.0, 0.1), nan, {}).ok());
  State wrong = displacedSpring();
  wrong.v.pop_back();
  EXPECT_FALSE(Simulator::create(test::oneSpring(1.0, 0.1), wrong, {}).ok());
}

}  // namespace
}  // namespace tissue::sim
