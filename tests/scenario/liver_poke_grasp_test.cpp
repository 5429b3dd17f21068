// The default scenario: the data/ liver as an embedded lattice (a volume), poked 12 mm deep by a
// sphere touching its render surface, grasped, lifted and released. 1000 frames with no NaN, no
// divergence event, a finite force every substep, and a poke force of the order a liver gives
// (Hertz: 4/3 E/(1-nu^2) sqrt(R) d^1.5 = 1 N for E = 5 kPa, R = 8 mm, d = 12 mm). About 3 s of
// simulation on a quiet core (was minutes with the surface model); still labelled "slow".
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "tissue/scenario/scenario_run.h"

namespace tissue::scenario {
namespace {

TEST(ScenarioRun, VolumetricLiverPokeAndGraspRuns1000FramesWithoutDivergence) {
  auto s = loadScenario(std::filesystem::path(TISSUE_TEST_DATA_DIR) / "scenarios" / "liver_poke_grasp.json");
  ASSERT_TRUE(s.ok()) << s.error().message;
  ASSERT_EQ(s->frames, 1000);
  ASSERT_EQ(s->springSource, SpringSource::Lattice);
  auto run = ScenarioRun::create(*s);
  ASSERT_TRUE(run.ok()) << run.error().message;
  const auto* tool = (*run)->instrument();
  ASSERT_NE(tool, nullptr);
  EXPECT_TRUE(tool->embedded());  // the tool touches the render surface, not the nodes
  std::vector<FrameMetrics> frames;
  double maxPushN = 0.0, maxPullN = 0.0;
  std::uint32_t maxGrasped = 0, maxContacts = 0;
  for (int f = 0; f < s->frames; ++f) {
    auto m = (*run)->advance();
    ASSERT_TRUE(m.ok()) << m.error().message;
    ASSERT_TRUE(m->finite) << "frame " << f;
    ASSERT_EQ(m->divergenceEvents, 0) << "frame " << f << ": " << m->divergenceReason;
    ASSERT_TRUE(m->degrade.empty()) << "frame " << f;
    // The haptic samples: one per substep, each finite.
    ASSERT_EQ(m->forceSamplesN.size(), static_cast<std::size_t>(s->substeps));
    for (const sim::Vec3d& sample : m->forceSamplesN)
      ASSERT_TRUE(sim::isFinite(sample)) << "frame " << f;
    // The poke (3 s) pushes the tool up (+z); the lift while grasping (6-7 s) pulls it down.
    if (m->grasped == 0) maxPushN = std::max(maxPushN, m->forceN.z);
    if (m->grasped > 0) maxPullN = std::max(maxPullN, -m->forceN.z);
    maxGrasped = std::max(maxGrasped, m->grasped);
    maxContacts = std::max(maxContacts, m->contacts);
    // Contacts are surface vertices, pushed out of the tool to within the tolerance.
    ASSERT_LE(m->contactDepthMm, 1e-3 * 8.0 + 1e-9) << "frame " << f;
    frames.push_back(*m);
  }
  const RunSummary summary = summarize(frames);
  EXPECT_EQ(summary.frames, 1000);
  EXPECT_EQ(summary.nanFrames, 0);
  EXPECT_EQ(summary.divergenceEvents, 0);
  // Of the order of a real liver's push back (about 1 N), not the surface model's 6 mN.
  EXPECT_GT(maxPushN, 0.3);
  EXPECT_LT(maxPushN, 3.0);
  EXPECT_GT(maxPullN, 0.1);
  EXPECT_GT(maxContacts, 5u);
  EXPECT_GT(maxGrasped, 0u);
  EXPECT_EQ(frames.back().grasped, 0u);                    // released
  EXPECT_NEAR(frames.back().forceMagnitudeN, 0.0, 1e-12);  // the tool has left
  for (const Float3& p : (*run)->positions())
    ASSERT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z));
}

}  // namespace
}  // namespace tissue::scenario
