// tissue-sim demo: the default headless scenario (the README's main job). The simulator runs
// data/scenarios/liver_poke_grasp.json (a sphere pokes, grasps, lifts and releases the data/
// liver, reporting the contact force every frame), keeps normals, tangent frames and the local planes of
// subsurface texture mapping in step, renders the organ before and after (when a GL context
// can be created) every frame through the library's loop (tissue::scene::OrganLoop: simulate, mesh,
// upload, render), writes every 100th frame and a report with the median and p99 of each phase.
// The run and its report are tissue::studies' (studies/demo_run.h); this command parses and prints.
#include "command.h"
#include "organ_data.h"
#include "output.h"
#include "tissue/studies/demo_run.h"

namespace tissue::sim_app {

void registerDemoCommand(CLI::App& app, const GlobalOptions& global, int& exitCode) {
  auto o = std::make_shared<studies::DemoConfig>();
  auto* cmd = app.add_subcommand(
      "demo", "the default headless scenario: poke and grasp the liver, update shading data, render, report");
  cmd->add_option("--out", o->outDir, "output folder for images and the report")->required();
  cmd->add_option("--scenario", o->scenarioFile,
                  "scenario file (default: data/scenarios/liver_poke_grasp.json, docs/SCENARIOS.md)");
  cmd->add_option("--mesh", o->meshFile, "organ mesh with UVs instead of the scenario's");
  cmd->add_option("--frames", o->frames, "frames to simulate (default: the scenario's)");
  cmd->add_option("--width", o->width, "image width in pixels (default 960)");
  cmd->add_option("--height", o->height, "image height in pixels (default 720)");
  cmd->add_option("--image-every", o->imageEvery,
                  "write the loop's rendered frame every this many frames (default 100)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--record", o->recordSession,
                  "also write the run as a session file (tissue-sim replay re-runs it; docs/SESSIONS.md)");
  cmd->add_option("--loop-width", o->loopWidth, "pixels of the frame rendered every loop frame (default 480)")
      ->check(CLI::Range(16, 8192));
  cmd->add_option("--loop-height", o->loopHeight, "pixels (default 360)")->check(CLI::Range(16, 8192));
  cmd->callback([o, &global, &exitCode] {
    o->dataDir = dataDir();
    if (o->frames < 0)
      return void(exitCode = fail("demo", "--frames must be at least 1 (0: the scenario's)"));
    exitCode = printRun("demo", global, studies::runDemo(*o, dataSceneSettings()), &studies::DemoRun::json);
  });
}

}  // namespace tissue::sim_app
