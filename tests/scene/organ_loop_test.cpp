// The library's per-frame loop without GL: simulate -> mesh, live input, and its errors.
#include <gtest/gtest.h>

#include <cmath>

#include "loop_fixture.h"
#include "tissue/mesh/load_mesh.h"
#include "tissue/scene/organ_loop.h"

namespace tissue::scene {
namespace {

Result<OrganLoop> makeLoop(const std::filesystem::path& scenarioFile) {
  auto s = scenario::loadScenario(scenarioFile);
  if (!s) return s.error();
  auto mesh = mesh::loadMesh(s->mesh, {.requireUvs = true});
  if (!mesh) return mesh.error();
  return OrganLoop::create(*s, std::move(*mesh));
}

std::filesystem::path testDir(const char* name) {
  return std::filesystem::path(TISSUE_TEST_OUTPUT_DIR) / "scene" / name;
}

TEST(OrganLoop, ThePokeMovesTheShadedSurfaceAndPushesBack) {
  auto loop = makeLoop(test::writePokedGrid(testDir("poke")));
  ASSERT_TRUE(loop.ok()) << loop.error().message;
  double maxForce = 0.0;
  for (int f = 0; f < 60; ++f) {
    auto frame = loop->advance();
    ASSERT_TRUE(frame.ok()) << frame.error().message;
    maxForce = std::max(maxForce, frame->simulation.forceMagnitudeN);
    EXPECT_GE(frame->ms.simulateMs, 0.0);
    EXPECT_GE(frame->ms.totalMs, frame->ms.simulateMs + frame->ms.meshMs - 1e-9);
    EXPECT_EQ(frame->ms.uploadMs, 0.0);  // no renderer attached: phases 3 and 4 do not run
    EXPECT_EQ(frame->ms.renderMs, 0.0);
  }
  EXPECT_GT(maxForce, 0.0);
  // The shaded surface is the simulated one: the centre went down, and its normal tilted or
  // stayed up while the render positions equal the simulated ones.
  const auto sim = loop->geometricPositions();
  const auto& surface = loop->surface();
  double lowest = 0.0;
  for (const auto& p : sim)
    lowest = std::min(lowest, double(p.z));
  EXPECT_LT(lowest, -0.5);  // the 3 mm sphere pushed the centre at least half a millimetre down
  for (std::size_t i = 0; i < surface.positions().size(); ++i) {
    const Float3 a = surface.positions()[i], b = sim[surface.mesh().geometricIndex[i]];
    EXPECT_EQ(a.x, b.x);
    EXPECT_EQ(a.y, b.y);
    EXPECT_EQ(a.z, b.z);
  }
}

TEST(OrganLoop, LiveInputTakesOverAndANaNPoseIsRefusedByName) {
  auto loop = makeLoop(test::writePokedGrid(testDir("live")));
  ASSERT_TRUE(loop.ok()) << loop.error().message;
  // Far above the grid: the script would come down, live input holds the tool up.
  InstrumentInput up;
  up.pose = sim::ToolPose{.position = {14.0, 14.0, 50.0}};
  for (int f = 0; f < 40; ++f) {
    auto frame = loop->advance(up);
    ASSERT_TRUE(frame.ok()) << frame.error().message;
    EXPECT_EQ(frame->simulation.forceMagnitudeN, 0.0);
  }
  InstrumentInput bad;
  bad.pose = sim::ToolPose{.position = {std::nan(""), 0.0, 0.0}};
  auto refused = loop->advance(bad);
  ASSERT_FALSE(refused.ok());
  EXPECT_NE(refused.error().message.find("not finite"), std::string::npos) << refused.error().message;
}

TEST(OrganLoop, GraspHoldsTheTissueWhileTheToolLifts) {
  auto loop = makeLoop(test::writePokedGrid(testDir("grasp")));
  ASSERT_TRUE(loop.ok()) << loop.error().message;
  InstrumentInput in;
  in.pose = sim::ToolPose{.position = {14.0, 14.0, 2.5}};  // the sphere's bottom 0.5 mm above the grid
  for (int f = 0; f < 10; ++f)
    ASSERT_TRUE(loop->advance(in).ok());
  in.grasp = true;
  in.pose = sim::ToolPose{.position = {14.0, 14.0, 6.0}};  // lift 3.5 mm
  double top = 0.0;
  for (int f = 0; f < 30; ++f) {
    auto frame = loop->advance(in);
    ASSERT_TRUE(frame.ok()) << frame.error().message;
    EXPECT_GT(frame->simulation.grasped, 0u);
  }
  for (const auto& p : loop->geometricPositions())
    top = std::max(top, double(p.z));
  EXPECT_GT(top, 2.0);  // grasped vertices follow the tool up
}

TEST(OrganLoop, AnotherMeshThanTheScenariosIsRefusedNamingBoth) {
  const auto file = test::writePokedGrid(testDir("mismatch"), 15);
  auto s = scenario::loadScenario(file);
  ASSERT_TRUE(s.ok());
  const auto other = test::writePokedGrid(testDir("mismatch_other"), 9);
  auto otherMesh = mesh::loadMesh(other.parent_path() / "grid.obj", {.requireUvs = true});
  ASSERT_TRUE(otherMesh.ok());
  auto loop = OrganLoop::create(*s, std::move(*otherMesh));
  ASSERT_FALSE(loop.ok());
  EXPECT_NE(loop.error().message.find("grid_poke.json"), std::string::npos) << loop.error().message;
  EXPECT_NE(loop.error().message.find("81"), std::string::npos) << loop.error().message;
}

}  // namespace
}  // namespace tissue::scene
