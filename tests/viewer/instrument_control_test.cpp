// The mouse-driven instrument: where its centre goes for a pick, a push, a release, a grasp.
#include "instrument_control.h"

#include <gtest/gtest.h>

#include "vec3_ops.h"

namespace tissue::viewer {
namespace {

constexpr float kRadius = 8.0f;
/// Straight down the z axis from 100 mm up: the surface point picked at z = 50 mm.
const Ray kRay{{0.0f, 0.0f, 100.0f}, {0.0f, 0.0f, -1.0f}};
constexpr float kHit = 50.0f;

/// Steps until the tool has arrived (at most `frames`).
void settle(InstrumentControl& tool, int frames = 200) {
  for (int i = 0; i < frames; ++i)
    tool.step();
}

TEST(InstrumentControlTest, APressTouchesThePickedPointThenPushesPastIt) {
  InstrumentControlSettings settings;
  settings.pressDepthMm = 0.0f;
  InstrumentControl tool({0.0f, 0.0f, 90.0f}, kRadius, settings);
  tool.press(kRay, kHit);
  settle(tool);
  // Depth 0: the sphere's front is exactly the picked point (50 mm), its centre a radius above.
  EXPECT_NEAR(tool.positionMm().z, 50.0f + kRadius, 1e-4f);
  tool.moveDepth(3.0);  // three 1 mm steps deeper
  settle(tool);
  EXPECT_NEAR(tool.positionMm().z, 47.0f + kRadius, 1e-4f);
  EXPECT_NEAR(tool.depthMm(), 3.0f, 1e-6f);
}

TEST(InstrumentControlTest, NoFrameMovesFartherThanTheStepLimit) {
  InstrumentControlSettings settings;
  settings.maxStepMm = 2.0f;
  InstrumentControl tool({60.0f, 0.0f, 90.0f}, kRadius, settings);
  tool.press(kRay, kHit);
  Float3 last = tool.positionMm();
  for (int i = 0; i < 100; ++i) {
    const Float3 now = tool.step();
    EXPECT_LE(length(now - last), 2.0f + 1e-4f);
    last = now;
  }
  EXPECT_NEAR(length(tool.positionMm() - tool.targetMm()), 0.0f, 1e-4f);  // and it arrives
}

TEST(InstrumentControlTest, ReleaseBacksOffUnlessGrasping) {
  InstrumentControl free({0.0f, 0.0f, 90.0f}, kRadius);
  free.press(kRay, kHit);
  settle(free);
  free.release(false);
  settle(free);
  // The front stops retractMm (15) in front of the picked point: clear of the surface.
  EXPECT_NEAR(free.positionMm().z - kRadius, kHit + 15.0f, 1e-4f);

  InstrumentControl holding({0.0f, 0.0f, 90.0f}, kRadius);
  holding.press(kRay, kHit);
  settle(holding);
  const Float3 held = holding.positionMm();
  holding.release(true);
  settle(holding);
  EXPECT_NEAR(length(holding.positionMm() - held), 0.0f, 1e-5f);
  holding.moveDepth(-10.0);  // lift the grasped tissue towards the eye
  settle(holding);
  EXPECT_NEAR(holding.positionMm().z, held.z + 10.0f, 1e-4f);
}

TEST(InstrumentControlTest, TheToolFollowsTheCursorAtThePickedDistanceAndDepthIsClamped) {
  InstrumentControl tool({0.0f, 0.0f, 90.0f}, kRadius);
  tool.press(kRay, kHit);
  const Ray tilted{kRay.origin, normalize({0.6f, 0.0f, -0.8f})};
  tool.aim(tilted);
  settle(tool);
  // Along the new ray at hit + depth (4 mm default) - radius.
  EXPECT_NEAR(length(tool.positionMm() - kRay.origin), kHit + 4.0f - kRadius, 1e-3f);
  EXPECT_NEAR(tool.positionMm().x / tool.positionMm().z, 0.0f + (0.6f * 46.0f) / (100.0f - 0.8f * 46.0f),
              1e-4f);
  tool.moveDepth(1000.0);
  EXPECT_FLOAT_EQ(tool.depthMm(), InstrumentControlSettings{}.maxDepthMm);
  tool.moveDepth(-1000.0);
  EXPECT_FLOAT_EQ(tool.depthMm(), InstrumentControlSettings{}.minDepthMm);
}

TEST(InstrumentControlTest, AParkedToolNeverPickedStaysWhereItStarted) {
  InstrumentControl tool({1.0f, 2.0f, 3.0f}, kRadius);
  settle(tool, 5);
  EXPECT_FLOAT_EQ(tool.positionMm().x, 1.0f);
  EXPECT_FLOAT_EQ(tool.positionMm().z, 3.0f);
  tool.aim(kRay);  // not held: ignored
  settle(tool, 5);
  EXPECT_FLOAT_EQ(tool.positionMm().z, 3.0f);
}

}  // namespace
}  // namespace tissue::viewer
