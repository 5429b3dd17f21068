// Recorded sessions: the file round trip, its errors, and deterministic replays.
#include <gtest/gtest.h>

#include <fstream>

#include "loop_fixture.h"
#include "tissue/core/atomic_file.h"
#include "tissue/mesh/load_mesh.h"
#include "tissue/scene/session.h"

namespace tissue::scene {
namespace {

std::filesystem::path testDir(const char* name) {
  return std::filesystem::path(TISSUE_TEST_OUTPUT_DIR) / "scene" / name;
}

Result<OrganLoop> makeLoop(const std::filesystem::path& scenarioFile, int frames = 0) {
  auto s = scenario::loadScenario(scenarioFile);
  if (!s) return s.error();
  if (frames > 0) s->frames = frames;
  auto mesh = mesh::loadMesh(s->mesh, {.requireUvs = true});
  if (!mesh) return mesh.error();
  return OrganLoop::create(*s, std::move(*mesh));
}

/// Records the scripted poke of the grid over `frames` frames.
Session recordPoke(const std::filesystem::path& scenarioFile, int frames) {
  auto loop = makeLoop(scenarioFile);
  EXPECT_TRUE(loop.ok()) << loop.error().message;
  SessionRecorder recorder(*loop);
  const render::Camera camera;
  const std::string method = "lit";
  for (int f = 0; f < frames; ++f) {
    EXPECT_TRUE(loop->advance().ok());
    recorder.recordFrame(*loop, &camera, &method);
  }
  return recorder.session();
}

/// Replays `session` and returns the final positions' fingerprint.
std::string replay(const Session& session) {
  auto loop = makeLoop(session.scenario);
  EXPECT_TRUE(loop.ok()) << loop.error().message;
  EXPECT_TRUE(checkSessionMatches(session, *loop).ok());
  for (std::size_t i = 0; i < session.frames.size(); ++i)
    EXPECT_TRUE(loop->advance(sessionInput(session, i)).ok());
  return positionsSha256(loop->geometricPositions());
}

TEST(Session, RoundTripKeepsEveryFrameExactly) {
  const auto scenarioFile = test::writePokedGrid(testDir("roundtrip"));
  const Session recorded = recordPoke(scenarioFile, 40);
  ASSERT_EQ(recorded.frames.size(), 40u);
  // The camera and method are stored once, when they change.
  EXPECT_TRUE(recorded.frames[0].camera.has_value());
  EXPECT_FALSE(recorded.frames[1].camera.has_value());
  EXPECT_EQ(recorded.frames[0].method.value_or(""), "lit");
  const auto file = testDir("roundtrip") / "session.json";
  ASSERT_TRUE(saveSession(recorded, file).ok());
  auto loaded = loadSession(file);
  ASSERT_TRUE(loaded.ok()) << loaded.error().message;
  EXPECT_EQ(std::filesystem::weakly_canonical(loaded->scenario),
            std::filesystem::weakly_canonical(scenarioFile));
  EXPECT_EQ(loaded->meshVertices, recorded.meshVertices);
  EXPECT_EQ(loaded->meshRestSha256, recorded.meshRestSha256);
  ASSERT_EQ(loaded->frames.size(), recorded.frames.size());
  for (std::size_t i = 0; i < recorded.frames.size(); ++i) {
    EXPECT_EQ(loaded->frames[i].toolPositionMm.z, recorded.frames[i].toolPositionMm.z) << i;
    EXPECT_EQ(loaded->frames[i].grasp, recorded.frames[i].grasp) << i;
  }
}

TEST(Session, TwoReplaysGiveBitIdenticalPositionsAndTheyMoved) {
  const auto scenarioFile = test::writePokedGrid(testDir("replay"));
  const Session session = recordPoke(scenarioFile, 50);
  const std::string first = replay(session), second = replay(session);
  EXPECT_EQ(first, second);
  EXPECT_EQ(first.size(), 64u);
  EXPECT_NE(first, session.meshRestSha256);  // the poke moved the surface
}

TEST(Session, ASessionFromAnotherMeshIsRefusedWithTheFix) {
  Session session = recordPoke(test::writePokedGrid(testDir("other_a"), 15), 5);
  auto loop = makeLoop(test::writePokedGrid(testDir("other_b"), 11));
  ASSERT_TRUE(loop.ok());
  auto check = checkSessionMatches(session, *loop);
  ASSERT_FALSE(check.ok());
  EXPECT_NE(check.error().message.find("recorded on a mesh of 225 vertices"), std::string::npos)
      << check.error().message;
  EXPECT_NE(check.error().message.find("replay it with the scenario it was recorded with"),
            std::string::npos);
}

TEST(Session, BadFilesNameTheFrameAndTheKey) {
  const auto dir = testDir("bad");
  std::filesystem::create_directories(dir);
  const std::string head =
      R"({"format": "tissue-session", "version": 1, "scenario": "s.json", "frame_time_s": 0.01, "mesh_vertices": 4, )";
  const std::pair<std::string, std::string> cases[] = {
      {head + R"("frames": [{"pose": [0, 0, 0]}, {"pose": [0, 1]}]})",
       "frames[1].pose: expected 3 numbers (mm)"},
      {head + R"("frames": [{"pose": [0, 0, 1e999]}]})", "not valid JSON"},
      {head + R"("frames": [{"pose": [0, 0, 0], "gasp": true}]})", "frames[0].gasp: unknown key"},
      {head + R"("frames": []})", "frames: expected a non-empty list"},
      {R"({"format": "tissue-session", "version": 2})", "version: expected 1"},
      {R"([1, 2])", "(top level): expected a JSON object"},
  };
  for (const auto& [text, expected] : cases) {
    ASSERT_TRUE(writeTextFileAtomic(dir / "s.session.json", text).ok());
    auto s = loadSession(dir / "s.session.json");
    ASSERT_FALSE(s.ok()) << text;
    EXPECT_NE(s.error().message.find(expected), std::string::npos) << s.error().message;
    EXPECT_NE(s.error().message.find("s.session.json"), std::string::npos) << s.error().message;
  }
}

TEST(Session, Sha256OfKnownBytes) {
  // One vertex (1, 2, 3): the 12 little-endian float bytes 00 00 80 3f 00 00 00 40 00 00 40 40,
  // hashed by coreutils sha256sum for the expected value.
  const Float3 p[] = {{1.0f, 2.0f, 3.0f}};
  EXPECT_EQ(positionsSha256(p), "8e628779e6a74ee0b36991c10158f63cafec7d340ad4e075592502c8708524dd");
}

}  // namespace
}  // namespace tissue::scene
