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

TEST(Divergence, ExplicitEulerPastTheLimitIsRolledBackAndRecovered) {
  // m = 1 g, k = 0.1 N/mm: the limit 2 sqrt(m/k) is 6.3 ms; frames of 20 ms in one step.
  SimulatorConfig config{.integrator = Integrator::ExplicitEuler, .frameTime = 0.02, .substeps = 1};
  auto sim = Simulator::create(test::oneSpring(1.0, 0.1), displacedSpring(), config);
  ASSERT_TRUE(sim.ok()) << sim.error().message;
  std::vector<DivergenceEvent> events;
  for (int f = 0; f < 200; ++f) {
    const FrameReport report = sim->advanceFrame();
    events.insert(events.end(), report.events.begin(), report.events.end());
    ASSERT_TRUE(allFinite(sim->state())) << "frame " << f;
    ASSERT_LE(maxStretch(sim->system(), sim->state().x), config.limits.maxStretch) << "frame " << f;
  }
  ASSERT_FALSE(events.empty());
  EXPECT_EQ(events.front().integrator, Integrator::ExplicitEuler);
  for (const auto& e : events)
    EXPECT_TRUE(e.recovered);
  // Explicit Euler gains energy at every h, so it ends replaced by a stable integrator.
  EXPECT_NE(sim->integrator(), Integrator::ExplicitEuler);
  // Once recovered, the motion stays bounded: no spring beyond twice its rest length.
  EXPECT_LT(maxStretch(sim->system(), sim->state().x), 2.0);
}

TEST(Divergence, SymplecticEulerPastTheLimitGainsSubsteps) {
  SimulatorConfig config{.integrator = Integrator::SymplecticEuler, .frameTime = 0.02, .substeps = 1};
  auto sim = Simulator::create(test::oneSpring(1.0, 0.1), displacedSpring(), config);
  ASSERT_TRUE(sim.ok());
  int events = 0;
  for (int f = 0; f < 50; ++f) {
    events += static_cast<int>(sim->advanceFrame().events.size());
    ASSERT_TRUE(allFinite(sim->state()));
  }
  EXPECT_GT(events, 0);
  EXPECT_EQ(sim->integrator(), Integrator::SymplecticEuler);
  EXPECT_LT(0.02 / sim->substeps(), 2.0 * std::sqrt(1.0 / 1e5));  // below the limit now
}

TEST(Divergence, RecoveredSubstepsRelaxAfterQuietFrames) {
  // Symplectic Euler at 20 ms > the 6.3 ms limit: one frame recovers with 4 substeps (5 ms).
  // After 5 quiet frames the simulator halves back to 2, which diverges once and doubles again:
  // the recovered setting is revisited, never kept for good, and never left unstable.
  SimulatorConfig config{.integrator = Integrator::SymplecticEuler, .frameTime = 0.02, .substeps = 1};
  config.recovery.relaxAfterFrames = 5;
  auto sim = Simulator::create(test::oneSpring(1.0, 0.1), displacedSpring(), config);
  ASSERT_TRUE(sim.ok());
  EXPECT_FALSE(sim->advanceFrame().events.empty());
  ASSERT_EQ(sim->substeps(), 4);
  std::vector<int> substeps;
  int events = 0;
  for (int f = 0; f < 30; ++f) {
    const FrameReport report = sim->advanceFrame();
    events += static_cast<int>(report.events.size());
    substeps.push_back(sim->substeps());
    ASSERT_TRUE(allFinite(sim->state()));
    ASSERT_LE(report.substeps, 4);
  }
  EXPECT_NE(std::find(substeps.begin(), substeps.end(), 2), substeps.end());  // it relaxed
  EXPECT_GT(events, 0);                                                       // 2 diverged
  EXPECT_EQ(sim->integrator(), Integrator::SymplecticEuler);
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
