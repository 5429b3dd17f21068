// The soak run (studies/soak_run.h), shortened: the shipped session cycled through every method
// twice; after the first cycle the live GL objects stay the same sample after sample, nothing
// diverges, and bad counts are refused with the fix. Needs GL (fails when no context comes up).
#include "tissue/studies/soak_run.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

namespace tissue::studies {
namespace {

const std::filesystem::path kData = TISSUE_TEST_DATA_DIR;

scene::SceneSettings dataSettings() {
  scene::SceneSettings s;
  s.materials.textureRoots = {TISSUE_TEST_GENERATED_DATA_DIR, kData};
  s.materialsDir = kData / "materials";
  s.sharedMeshesDir = std::filesystem::path(TISSUE_TEST_SHARED_DIR) / "meshes";
  return s;
}

TEST(SoakRun, EveryMethodTwiceLeavesTheGlObjectsAsTheFirstCycleLeftThem) {
  const SoakConfig config{.session = kData / "sessions" / "liver_poke_grasp.json",
                          .frames = 100,
                          .warmupFrames = 50,
                          .sampleEvery = 10,
                          .methodEvery = 10,
                          .width = 32,
                          .height = 24};
  auto run = soakSession(config, dataSettings());
  ASSERT_TRUE(run) << run.error().message;
  const auto j = nlohmann::json::parse(*run);
  EXPECT_EQ(j["frames"], 100);
  EXPECT_EQ(j["samples"].size(), 10u);
  EXPECT_EQ(j["gl_ok"], true) << j["samples"].dump();
  EXPECT_EQ(j["gl_objects"]["min"], j["gl_objects"]["max"]);
  EXPECT_GT(j["gl_objects"]["after_warmup"].get<int>(), 10);  // targets, meshes, programs of five methods
  EXPECT_GT(j["rss_kb"]["after_warmup"].get<long>(), 0);
  EXPECT_EQ(j["nan_frames"], 0);
  for (const char* key : {"median", "p99", "max"})
    EXPECT_GT(j["frame_ms"][key].get<double>(), 0.0) << key;
}

TEST(SoakRun, AWarmUpThatMissesAMethodIsRefusedWithTheFix) {
  auto run = soakSession({.session = kData / "sessions" / "liver_poke_grasp.json",
                          .frames = 100,
                          .warmupFrames = 20,
                          .sampleEvery = 10,
                          .methodEvery = 10},
                         dataSettings());
  ASSERT_FALSE(run);
  EXPECT_NE(run.error().message.find("at least 50"), std::string::npos) << run.error().message;
}

}  // namespace
}  // namespace tissue::studies
