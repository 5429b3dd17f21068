// The mesh work follows the method (issue 16): without GL, an organ whose method reads no
// planes does no plane re-fit nor tangent work while it is poked, a ray-marched one does, and a
// loop that skipped them brings them up to date equal to one that kept them every frame.
#include <gtest/gtest.h>

#include "loop_fixture.h"
#include "tissue/mesh/load_mesh.h"
#include "tissue/scene/scene.h"

namespace tissue::scene {
namespace {

std::filesystem::path testDir(const char* name) {
  return std::filesystem::path(TISSUE_TEST_OUTPUT_DIR) / "scene" / name;
}

TEST(MeshWork, ALitOrganBeingPokedDoesNoPlaneRefitARayMarchedOneDoes) {
  SceneSettings settings;
  settings.gl = false;
  auto scene = Scene::create({}, settings);
  ASSERT_TRUE(scene.ok()) << scene.error().message;
  const auto poke = test::writePokedGrid(testDir("mesh_work"));
  auto lit = scene->addOrgan({.scenario = poke, .method = render::ShadingMethod::Lit});
  auto marched = scene->addOrgan({.scenario = poke, .method = render::ShadingMethod::RayMarch});
  auto blurred = scene->addOrgan({.scenario = poke, .method = render::ShadingMethod::Separable});
  ASSERT_TRUE(lit.ok() && marched.ok() && blurred.ok());
  LoopRecord litRecord, marchedRecord, blurredRecord;
  for (int f = 0; f < 40; ++f) {
    for (auto [id, record] : {std::pair{*lit, &litRecord}, std::pair{*marched, &marchedRecord},
                              std::pair{*blurred, &blurredRecord}}) {
      auto frame = scene->advance(id);
      ASSERT_TRUE(frame.ok()) << frame.error().message;
      record->add(*frame, *scene->loop(id));
    }
  }
  // The same poke moves all three alike.
  const auto a = scene->loop(*lit)->geometricPositions(), b = scene->loop(*marched)->geometricPositions();
  for (std::size_t i = 0; i < a.size(); ++i)
    ASSERT_EQ(a[i], b[i]);
  // The grid has no normal map: lit and separable read neither planes nor tangents.
  EXPECT_EQ(litRecord.planeFrames, 0);
  EXPECT_EQ(litRecord.tangentFrames, 0);
  EXPECT_EQ(litRecord.refittedFraction, 0.0);
  EXPECT_EQ(blurredRecord.planeFrames, 0);
  EXPECT_EQ(blurredRecord.tangentFrames, 0);
  EXPECT_EQ(marchedRecord.planeFrames, 40);
  EXPECT_EQ(marchedRecord.tangentFrames, 40);
  EXPECT_GT(marchedRecord.refittedFraction, 0.0);  // the poke re-fitted planes
  EXPECT_FALSE(scene->loop(*lit)->surface().planesCurrent());
  EXPECT_TRUE(scene->loop(*marched)->surface().planesCurrent());
}

TEST(MeshWork, AllWorkEveryFrameWhenTheSceneAsksForIt) {
  SceneSettings settings;
  settings.gl = false;
  settings.meshWorkFollowsMethod = false;  // an inspection that reads every attribute
  auto scene = Scene::create({}, settings);
  ASSERT_TRUE(scene.ok()) << scene.error().message;
  auto lit = scene->addOrgan({.scenario = test::writePokedGrid(testDir("mesh_work_all"))});
  ASSERT_TRUE(lit.ok());
  LoopRecord record;
  for (int f = 0; f < 10; ++f) {
    auto frame = scene->advance(*lit);
    ASSERT_TRUE(frame.ok());
    record.add(*frame, *scene->loop(*lit));
  }
  EXPECT_EQ(record.planeFrames, 10);
  EXPECT_EQ(record.tangentFrames, 10);
}

Result<OrganLoop> makeLoop(const std::filesystem::path& scenarioFile, const mesh::PlaneRefitSettings& refit) {
  auto s = scenario::loadScenario(scenarioFile);
  if (!s) return s.error();
  auto mesh = mesh::loadMesh(s->mesh, {.requireUvs = true});
  if (!mesh) return mesh.error();
  return OrganLoop::create(*s, std::move(*mesh), {.refit = refit});
}

// After N poked frames without planes and tangents (lit), switching them on (the ray march)
// gives what a loop that kept them every frame holds.
void expectSwitchCatchesUp(const mesh::PlaneRefitSettings& refit, const char* dir) {
  const auto poke = test::writePokedGrid(testDir(dir));
  auto always = makeLoop(poke, refit);
  auto lazy = makeLoop(poke, refit);
  ASSERT_TRUE(always.ok() && lazy.ok());
  lazy->setMeshWork({.planes = false, .tangents = false});
  for (int f = 0; f < 45; ++f) {
    ASSERT_TRUE(always->step().ok());
    auto frame = lazy->step();
    ASSERT_TRUE(frame.ok());
    EXPECT_FALSE(frame->mesh.planes || frame->mesh.tangents);
    EXPECT_EQ(frame->mesh.refit.refittedPlanes, 0u);
  }
  const mesh::SurfaceWork fresh = lazy->setMeshWork({});
  EXPECT_TRUE(fresh.planes && fresh.tangents);
  const auto& s = lazy->surface();
  const auto& r = always->surface();
  for (std::size_t i = 0; i < s.tangents().size(); ++i)
    ASSERT_EQ(s.tangents()[i], r.tangents()[i]) << "vertex " << i;
  const auto dev = mesh::comparePlanes(s.planes(), r.planes());
  if (refit.maxNormalErrorRad == 0.0) {
    for (std::size_t i = 0; i < s.planes().size(); ++i)
      ASSERT_EQ(s.planes()[i], r.planes()[i]) << "vertex " << i;
  } else {
    EXPECT_LE(dev.maxAngleRad, 2.0 * refit.maxNormalErrorRad);  // each within the bound of a full re-fit
    EXPECT_LT(dev.maxOffsetMm, 1e-3);
  }
  // And the frames after the switch keep them current, equal again.
  for (int f = 0; f < 5; ++f) {
    ASSERT_TRUE(always->step().ok());
    auto frame = lazy->step();
    ASSERT_TRUE(frame.ok());
    EXPECT_TRUE(frame->mesh.planes && frame->mesh.tangents);
  }
  EXPECT_LE(mesh::comparePlanes(s.planes(), r.planes()).maxAngleRad, 2.0 * refit.maxNormalErrorRad);
}

TEST(MeshWork, ASwitchToTheRayMarchBringsExactPlanesAndTangentsUpToDate) {
  expectSwitchCatchesUp({.maxNormalErrorRad = 0.0}, "mesh_work_exact");
}

TEST(MeshWork, ASwitchToTheRayMarchBringsTolerantPlanesWithinTheirBound) {
  expectSwitchCatchesUp({}, "mesh_work_tolerant");
}

}  // namespace
}  // namespace tissue::scene
