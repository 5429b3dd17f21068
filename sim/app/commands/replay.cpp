// tissue-sim replay SESSION: re-runs a recorded session (instrument pose and grasp per frame)
// headless through the library's loop (tissue::scene::OrganLoop), deterministically: the same
// thread count gives bit-identical positions, fingerprinted by positions_sha256. With --render
// every frame is also uploaded and rendered (the deformation-plus-render performance test).
// The replay and its report are tissue::studies' (studies/replay_run.h).
#include "command.h"
#include "organ_data.h"
#include "output.h"
#include "tissue/studies/replay_run.h"

namespace tissue::sim_app {

void registerReplayCommand(CLI::App& app, const GlobalOptions& global, int& exitCode) {
  auto o = std::make_shared<studies::ReplayConfig>();
  auto method = std::make_shared<std::string>("lit");
  auto* cmd = app.add_subcommand(
      "replay",
      "re-run a recorded session headless and deterministically (the deformation-plus-render test)");
  cmd->add_option("session", o->session, "session file (data/sessions/*.json, docs/SESSIONS.md)")->required();
  cmd->add_flag("--render", o->render, "also upload and render every frame (with --method, offscreen)");
  cmd->add_option("--pvd", o->pvdDir,
                  "write the ParaView series (.pvd, one .vtp per frame) into this folder");
  cmd->add_option("--out", o->outDir, "folder for report.json, frames.csv and (with --render) frame images");
  cmd->add_option("--width", o->width, "rendered width, pixels (default 480)")->check(CLI::Range(16, 8192));
  cmd->add_option("--height", o->height, "rendered height, pixels (default 360)")
      ->check(CLI::Range(16, 8192));
  cmd->add_option("--image-every", o->imageEvery,
                  "with --render and --out: write every this many frames (100)")
      ->check(CLI::PositiveNumber);
  cmd->add_option(
      "--method", *method,
      "the organ's shading method (default lit): what --render draws and what the mesh phase "
      "keeps current (local planes for ray-march; tangents for a normal map, ray-march, parallax)");
  cmd->callback([o, method, &global, &exitCode] {
    auto parsed = scene::parseShadingMethod(*method);
    if (!parsed) {
      exitCode = fail("replay", "--" + parsed.error().message);
      return;
    }
    o->method = *parsed;
    exitCode = printRun("replay", global, studies::replaySession(*o, dataSceneSettings()));
  });
}

}  // namespace tissue::sim_app
