// tissue-sim soak [SESSION] [--frames N]: the soak run (issue 14, item 5): a recorded session
// replayed over and over through the library's loop with every shading method in turn; after the
// warm-up the resident memory may grow by at most 1 MB and the live GL objects must stay constant
// (tissue/studies/soak_run.h). Exit 1 when either verdict fails.
#include <iostream>

#include "cli_options.h"
#include "command.h"
#include "organ_data.h"
#include "output.h"
#include "tissue/studies/soak_run.h"

namespace tissue::sim_app {

void registerSoakCommand(CLI::App& app, const GlobalOptions& global, int& exitCode) {
  auto o = std::make_shared<studies::SoakConfig>();
  auto session = std::make_shared<std::string>();
  auto* cmd = app.add_subcommand(
      "soak", "replay a session for many frames, every method in turn: memory and GL objects must stay flat");
  cmd->add_option("session", *session, "session file (default data/sessions/liver_poke_grasp.json)");
  cmd->add_option("--frames", o->frames, "frames in all (default 100000)")->check(CLI::PositiveNumber);
  cmd->add_option("--warmup", o->warmupFrames, "frames before the baseline (default 5000)");
  cmd->add_option("--sample-every", o->sampleEvery, "frames between samples (default 1000)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--method-every", o->methodEvery, "frames per shading method (default 200; 0: lit only)");
  addImageSizeOptions(cmd, o->width, o->height);  // checked by studies::soakSession
  cmd->add_option("--map-size", o->mapSize, "texture-space and parallax map texels a side (default 256)");
  cmd->callback([o, session, &global, &exitCode] {
    o->session =
        session->empty() ? dataDir() / "sessions" / "liver_poke_grasp.json" : std::filesystem::path(*session);
    o->onProgress = [](const std::string& line) { std::cerr << "tissue-sim " << line << "\n"; };
    auto run = studies::soakSession(*o, dataSceneSettings());
    exitCode = printRun("soak", global, run);
    if (exitCode == 0 && (run->find("\"rss_ok\": false") != std::string::npos ||
                          run->find("\"gl_ok\": false") != std::string::npos)) {
      std::cerr
          << "tissue-sim soak: memory or GL objects grew after the warm-up (rss_ok, gl_ok in the report)\n";
      exitCode = 1;
    }
  });
}

}  // namespace tissue::sim_app
