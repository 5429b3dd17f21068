// The main job and replay as library calls (studies/demo_run.h, replay_run.h), shortened: 60
// frames of the data scenario through the loop with every method's snapshot, the report files
// and their figures, the recorded session replayed twice to the same positions, and bad input.
// Needs GL (a headless context; the test fails when none comes up).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "tissue/studies/demo_run.h"
#include "tissue/studies/replay_run.h"
#include "tissue/studies/soak_run.h"

namespace tissue::studies {
namespace {

const std::filesystem::path kData = TISSUE_TEST_DATA_DIR;
const std::filesystem::path kOut = std::filesystem::path(TISSUE_TEST_OUTPUT_DIR) / "demo_run";

scene::SceneSettings dataSettings() {
  scene::SceneSettings s;
  s.materials.textureRoots = {TISSUE_TEST_GENERATED_DATA_DIR, kData};
  s.materialsDir = kData / "materials";
  s.sharedMeshesDir = std::filesystem::path(TISSUE_TEST_SHARED_DIR) / "meshes";
  return s;
}

std::string fileText(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(DemoRun, ShortMainJobWritesItsReportAndReplaysBitForBit) {
  std::filesystem::remove_all(kOut);
  DemoConfig config{.outDir = kOut / "demo",
                    .dataDir = kData,
                    .frames = 60,
                    .imageEvery = 30,
                    .recordSession = kOut / "session.json",
                    .loopWidth = 64,
                    .loopHeight = 48,
                    .width = 160,
                    .height = 120,
                    .logContext = false};
  auto run = runDemo(config, dataSettings());
  ASSERT_TRUE(run) << run.error().message;
  const auto j = nlohmann::json::parse(run->json);
  ASSERT_FALSE(j.contains("render_skipped")) << j["render_skipped"];

  // Step 1: the stdout object holds the run's figures, the loop's phases and every method.
  EXPECT_EQ(j["frames"], 60);
  EXPECT_EQ(j["image_every"], 30);
  EXPECT_EQ(j["loop_image_size"], nlohmann::json({64, 48}));
  EXPECT_EQ(j["instrument"]["frames"], 60);
  EXPECT_FALSE(j["instrument"].contains("contact_force_N_per_frame"));  // stdout: the summary only
  EXPECT_EQ(j["phases_ms"].size(), scene::LoopPhaseSamples{}.phases.size());
  for (const char* key :
       {"render", "render_separable", "texture_space", "parallax", "raymarch", "embedded_scene", "methods",
        "sequence", "refit", "mesh", "scenario", "material", "vertices"})
    EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_EQ(j["raymarch"].size(), 2u);  // the whole organ and the close-up (frameForRayMarch)
  EXPECT_FALSE(j["embedded_scene"].contains("skipped")) << j["embedded_scene"];
  // The embedded scene under two frame budgets: each organ's choice is one of the five methods
  // at a positive predicted cost, the lit tier wherever it fell back, and each budget's frame.
  const auto& budgets = j["embedded_scene"]["budgets"];
  ASSERT_TRUE(budgets.is_array()) << budgets;  // not {"skipped": why}
  ASSERT_EQ(budgets.size(), 2u) << j["embedded_scene"];
  const std::set<std::string> methods{"lit", "separable", "texture-space", "ray-march", "parallax"};
  for (const auto& b : budgets) {
    ASSERT_EQ(b["choices"].size(), 2u) << b;
    for (const auto& c : b["choices"]) {
      EXPECT_TRUE(methods.count(c["method"].get<std::string>())) << c;
      EXPECT_GT(c["footprint_px"].get<double>(), 0.0) << c;
      EXPECT_GT(c["predicted_ms"].get<double>(), 0.0) << c;
      if (c["fallback"].get<bool>()) {
        EXPECT_EQ(c["method"], "lit") << c;
      }
    }
    EXPECT_GT(b["frame_ms"]["median"].get<double>(), 0.0);
    EXPECT_GT(std::filesystem::file_size(config.outDir / b["image"].get<std::string>()), 0u);
  }
  EXPECT_LT(budgets[0]["budget_ms"].get<double>(), budgets[1]["budget_ms"].get<double>());
  EXPECT_EQ(j["sequence"]["panels"], nlohmann::json({"frames/frame_0030.png", "frames/frame_0060.png"}));

  // Step 2: the files: report.json with every frame's force, report.md with its tables.
  ASSERT_EQ(run->report.files.size(), 2u);
  EXPECT_EQ(run->report.files[0].name, "report.json");
  EXPECT_EQ(run->report.files[1].name, "report.md");
  const auto file = nlohmann::json::parse(fileText(config.outDir / "report.json"));
  EXPECT_EQ(file["instrument"]["contact_force_N_per_frame"].size(), 60u);
  EXPECT_EQ(file["frames"], j["frames"]);
  const std::string md = fileText(config.outDir / "report.md");
  EXPECT_EQ(md, run->report.files[1].text);
  EXPECT_NE(md.find("| phase | median | p99 | max |\n|---|---|---|---|\n"), std::string::npos);
  for (const auto& [phase, values] : scene::LoopPhaseSamples{}.phases)
    EXPECT_NE(md.find("| " + phase + " | "), std::string::npos) << phase;
  EXPECT_NE(md.find("| frame | F_x (N) | F_y (N) | F_z (N) |\n|---|---|---|---|\n| 0 | "), std::string::npos);
  EXPECT_NE(md.find("\n| 50 | "), std::string::npos);
  for (const char* png :
       {"frames/frame_0030.png", "frames/frame_0060.png", "frame_sequence.png", "frame_rest.png",
        "frame_poked.png", "frame_poked_separable.png", "frame_poked_texture_space.png",
        "frame_poked_raymarch.png", "frame_poked_raymarch_closeup.png", "frame_poked_parallax.png",
        "frame_poked_methods.png", "frame_embedded_scene.png", "frames.csv"})
    EXPECT_GT(std::filesystem::file_size(config.outDir / png), 0u) << png;

  // Step 3: the recorded session, replayed without and with rendering: the same positions.
  auto plain = replaySession({.session = config.recordSession}, dataSettings());
  ASSERT_TRUE(plain) << plain.error().message;
  auto rendered = replaySession({.session = config.recordSession,
                                 .render = true,
                                 .outDir = kOut / "replay",
                                 .imageEvery = 30,
                                 .logContext = false},
                                dataSettings());
  ASSERT_TRUE(rendered) << rendered.error().message;
  const auto a = nlohmann::json::parse(*plain), b = nlohmann::json::parse(*rendered);
  EXPECT_EQ(a["frames"], 60);
  EXPECT_EQ(a["rendered"], false);
  EXPECT_EQ(b["rendered"], true);
  EXPECT_EQ(a["positions_sha256"].get<std::string>().size(), 64u);
  EXPECT_EQ(a["positions_sha256"], b["positions_sha256"]);
  EXPECT_EQ(a["phases_ms"].size(), j["phases_ms"].size());
  EXPECT_FALSE(a.contains("out"));
  EXPECT_EQ(b["out"], (kOut / "replay").string());
  for (const char* f : {"frame_0030.png", "frame_0060.png", "report.json", "frames.csv"})
    EXPECT_GT(std::filesystem::file_size(kOut / "replay" / f), 0u) << f;
  EXPECT_EQ(nlohmann::json::parse(fileText(kOut / "replay" / "report.json"))["positions_sha256"],
            b["positions_sha256"]);
}

TEST(DemoRun, BadInputIsAnErrorNamingIt) {
  DemoConfig negative{.outDir = kOut / "bad", .dataDir = kData, .frames = -1};
  auto demo = runDemo(negative, dataSettings());
  ASSERT_FALSE(demo);
  EXPECT_NE(demo.error().message.find("frames"), std::string::npos) << demo.error().message;
  auto replay = replaySession({.session = kOut / "no_such_session.json"}, dataSettings());
  ASSERT_FALSE(replay);
  EXPECT_NE(replay.error().message.find("no_such_session.json"), std::string::npos) << replay.error().message;
}

// The soak run (studies/soak_run.h), shortened: the shipped session through every method twice;
// after the first cycle the live GL objects stay the same, and bad counts are refused with the fix.
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
