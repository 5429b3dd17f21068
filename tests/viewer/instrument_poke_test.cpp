// The stand-in poke on a flat 1 mm grid: the region, the depth, the push speed and relaxation.
#include "instrument_poke.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "vec3_ops.h"

namespace tissue::viewer {
namespace {

/// A 61 x 61 grid in z = 0 with 1 mm spacing, centred on the origin (a vertex).
std::vector<Float3> grid() {
  std::vector<Float3> positions;
  for (int y = -30; y <= 30; ++y)
    for (int x = -30; x <= 30; ++x)
      positions.push_back({float(x), float(y), 0.0f});
  return positions;
}

float maxDisplacementMm(const InstrumentPoke& poke) {
  float m = 0.0f;
  for (const Float3& d : poke.displacements())
    m = std::max(m, length(d));
  return m;
}

/// Pushes at the origin along -z (straight into the grid) for `seconds`.
InstrumentPoke pushedPoke(const std::vector<Float3>& rest, float seconds) {
  InstrumentPoke poke(rest);
  poke.press({0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, -2.0f}, rest);
  poke.step(seconds);
  return poke;
}

TEST(InstrumentPokeTest, OnlyVerticesWithinTheRadiusMove) {
  const auto rest = grid();
  const InstrumentPoke poke = pushedPoke(rest, 1.0f);
  const float radius = poke.settings().radiusMm;
  int moved = 0;
  for (std::size_t i = 0; i < rest.size(); ++i) {
    const float r = length(rest[i]);
    const Float3 d = poke.displacements()[i];
    if (r >= radius) {
      EXPECT_EQ(d, Float3{}) << "vertex at r = " << r << " mm moved";
    } else {
      EXPECT_LT(d.z, 0.0f) << "vertex at r = " << r << " mm did not move";
      EXPECT_EQ(d.x, 0.0f);  // along the instrument's direction only
      EXPECT_EQ(d.y, 0.0f);
      ++moved;
    }
    EXPECT_EQ(poke.positions()[i], rest[i] + d);
  }
  EXPECT_GT(moved, 600);  // about pi 15^2 grid points
}

TEST(InstrumentPokeTest, DeepestDisplacementIsTheDepthAtTheContact) {
  const auto rest = grid();
  const InstrumentPoke poke = pushedPoke(rest, 1.0f);
  const std::size_t centre = 30 * 61 + 30;
  EXPECT_FLOAT_EQ(poke.depthMm(), poke.settings().maxDepthMm);
  EXPECT_FLOAT_EQ(poke.displacements()[centre].z, -poke.settings().maxDepthMm);
  EXPECT_FLOAT_EQ(maxDisplacementMm(poke), poke.settings().maxDepthMm);
  // Cosine falloff: half the depth at half the radius (7.5 mm lies between grid points; 5 mm:
  // 0.5 (1 + cos(pi / 3)) = 0.75).
  EXPECT_NEAR(poke.displacements()[centre + 5].z, -0.75f * poke.settings().maxDepthMm, 1e-5f);
}

TEST(InstrumentPokeTest, PushDeepensAtItsSpeedWhileHeld) {
  const auto rest = grid();
  InstrumentPoke poke(rest);
  poke.press({0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, -1.0f}, rest);
  EXPECT_TRUE(poke.step(0.05f));
  EXPECT_NEAR(poke.depthMm(), 0.05f * poke.settings().pushSpeedMmPerS, 1e-5f);
  EXPECT_NEAR(maxDisplacementMm(poke), poke.depthMm(), 1e-5f);
  for (int i = 0; i < 100; ++i)
    poke.step(0.05f);
  EXPECT_FLOAT_EQ(poke.depthMm(), poke.settings().maxDepthMm);
}

TEST(InstrumentPokeTest, ReleaseRelaxesToRestWithinTheRelaxTime) {
  const auto rest = grid();
  InstrumentPoke poke = pushedPoke(rest, 1.0f);
  poke.release();
  const float depth = poke.settings().maxDepthMm;
  const float dt = 1.0f / 60.0f;  // s, a 60 Hz frame
  const int framesToRelax = int(poke.settings().relaxTimeS / dt + 0.5f);
  for (int frame = 0; frame < framesToRelax / 2; ++frame)
    poke.step(dt);
  EXPECT_GT(maxDisplacementMm(poke), 0.05f * depth) << "relaxation is gradual, not a jump";
  for (int frame = framesToRelax / 2; frame < framesToRelax; ++frame)
    poke.step(dt);
  EXPECT_LE(maxDisplacementMm(poke), 0.01f * depth * 1.001f)
      << "after " << poke.settings().relaxTimeS << " s";
  // Some frames later it is exactly at rest and stops reporting changes.
  for (int frame = 0; frame < 5 * framesToRelax; ++frame)
    poke.step(dt);
  EXPECT_EQ(maxDisplacementMm(poke), 0.0f);
  EXPECT_TRUE(std::equal(rest.begin(), rest.end(), poke.positions().begin()));
  EXPECT_FALSE(poke.step(dt));
}

TEST(InstrumentPokeTest, ResetReturnsToRestAtOnce) {
  const auto rest = grid();
  InstrumentPoke poke = pushedPoke(rest, 0.1f);
  poke.reset();
  EXPECT_FALSE(poke.pressed());
  EXPECT_TRUE(std::equal(rest.begin(), rest.end(), poke.positions().begin()));
  EXPECT_FALSE(poke.step(0.1f));
}

TEST(InstrumentPokeTest, AContactOffTheMeshMovesNothing) {
  const auto rest = grid();
  InstrumentPoke poke(rest);
  poke.press({500.0f, 0.0f, 0.0f}, {0.0f, 0.0f, -1.0f}, rest);
  poke.step(1.0f);
  EXPECT_EQ(maxDisplacementMm(poke), 0.0f);
}

}  // namespace
}  // namespace tissue::viewer
