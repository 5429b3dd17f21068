// tissue-sim replay SESSION: re-runs a recorded session (instrument pose and grasp per frame)
// headless through the library's loop (tissue::scene::OrganLoop), deterministically: the same
// thread count gives bit-identical positions, fingerprinted by positions_sha256. With --render
// every frame is also uploaded and rendered (the deformation-plus-render performance test).
#include <cstdio>
#include <memory>
#include <optional>

#include "command.h"
#include "gl_environment.h"
#include "loop_setup.h"
#include "output.h"
#include "tissue/core/atomic_file.h"
#include "tissue/core/image.h"
#include "tissue/core/statistics.h"
#include "tissue/scenario/scenario_run.h"
#include "tissue/scene/session.h"

namespace tissue::sim_app {
namespace {

struct ReplayOptions {
  std::string session;
  bool render = false;
  std::filesystem::path outDir;
  int width = 480, height = 360;
  int imageEvery = 100;
};

Result<nlohmann::json> replay(const ReplayOptions& o) {
  // Setup: the session, and the scenario it was recorded with in a scene (GL with --render).
  auto session = scene::loadSession(o.session);
  if (!session) return session.error();
  std::unique_ptr<context::GlContext> context;
  if (o.render) {
    auto made = createAppContext(offscreenRequest());  // the scene draws offscreen
    if (!made) return made.error();
    context = std::move(*made);
  }
  auto scene = makeLoopScene(context.get());
  if (!scene) return scene.error();
  if (auto added = scene->addOrgan({.scenario = session->scenario}); !added) return added.error();
  const scene::OrganLoop& loop = *scene->loop(0);
  if (auto match = scene::checkSessionMatches(*session, loop); !match) return match.error();

  // The frames, each one pass through the library's loop with the recorded input.
  scene::LoopRecord record;
  Image8 image;
  for (std::size_t i = 0; i < session->frames.size(); ++i) {
    auto f =
        scene->advance(0, scene::sessionInput(*session, i), o.render ? &image : nullptr, o.width, o.height);
    if (!f) return Error{session->file.string() + ": frame " + std::to_string(i) + ": " + f.error().message};
    record.add(*f, loop);
    if (o.render && !o.outDir.empty() && (i + 1) % std::size_t(o.imageEvery) == 0) {
      char name[32];
      std::snprintf(name, sizeof name, "frame_%04zu.png", i + 1);
      if (auto w = writePng(o.outDir / name, image); !w) return w.error();
    }
  }

  // Report: the fingerprint, the frame times and every phase.
  const auto summary = scenario::summarize(record.frames);
  const auto& total = record.phases.phases.back().second;
  const auto frameMs = summarizeSamples(total);
  nlohmann::json j{
      {"session", session->file.string()},
      {"scenario", loop.run().scenario().file.string()},
      {"frames", session->frames.size()},
      {"rendered", o.render},
      {"positions_sha256", scene::positionsSha256(loop.geometricPositions())},
      {"frame_ms",
       {{"median", rounded(frameMs.median)}, {"p99", rounded(frameMs.p99)}, {"max", rounded(frameMs.max)}}},
      {"phases_ms", phaseReport(record.phases)},
      {"max_contact_force_N", rounded(summary.maxForceN)},
      {"divergence_events", summary.divergenceEvents},
      {"nan_frames", summary.nanFrames}};
  if (!o.outDir.empty()) {
    if (auto w = writeTextFileAtomic(o.outDir / "frames.csv", scenario::framesCsv(record.frames)); !w)
      return w.error();
    if (auto w = writeTextFileAtomic(o.outDir / "report.json", j.dump(2) + "\n"); !w) return w.error();
    j["out"] = o.outDir.string();
  }
  return j;
}

}  // namespace

void registerReplayCommand(CLI::App& app, const GlobalOptions& global, int& exitCode) {
  auto o = std::make_shared<ReplayOptions>();
  auto* cmd = app.add_subcommand(
      "replay",
      "re-run a recorded session headless and deterministically (the deformation-plus-render test)");
  cmd->add_option("session", o->session, "session file (data/sessions/*.json, docs/SESSIONS.md)")->required();
  cmd->add_flag("--render", o->render, "also upload and render every frame (lit, offscreen)");
  cmd->add_option("--out", o->outDir, "folder for report.json, frames.csv and (with --render) frame images");
  cmd->add_option("--width", o->width, "rendered width, pixels (default 480)")->check(CLI::Range(16, 8192));
  cmd->add_option("--height", o->height, "rendered height, pixels (default 360)")
      ->check(CLI::Range(16, 8192));
  cmd->add_option("--image-every", o->imageEvery,
                  "with --render and --out: write every this many frames (100)")
      ->check(CLI::PositiveNumber);
  cmd->callback([o, &global, &exitCode] {
    auto report = replay(*o);
    if (!report) {
      exitCode = fail("replay", report.error().message);
      return;
    }
    printResult(global, *report);
  });
}

}  // namespace tissue::sim_app
