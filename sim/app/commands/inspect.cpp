// tissue-sim inspect SCENARIO_OR_SESSION [--frame N] --out DIR [--pvd DIR]: runs a scenario (or
// replays a recorded session) to frame N through the library's loop and writes the VTK inspection
// views of that frame (PNG with colour bars, and a .vtp each); with --pvd also the ParaView series
// of frames 1..N and its cost. The run is tissue::studies' (studies/inspect_run.h).
#include "command.h"
#include "organ_data.h"
#include "output.h"
#include "tissue/studies/inspect_run.h"

namespace tissue::sim_app {

void registerInspectCommand(CLI::App& app, const GlobalOptions& global, int& exitCode) {
  auto o = std::make_shared<studies::InspectConfig>();
  auto* cmd = app.add_subcommand("inspect",
                                 "write the VTK inspection views (PNG + .vtp) of one frame of a "
                                 "scenario or a recorded session");
  cmd->add_option("input", o->input, "scenario (data/scenarios/*.json) or session file")->required();
  cmd->add_option("--frame", o->frame, "frames to simulate first (0: rest; default: the last)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--out", o->outDir, "folder for the views")->required();
  cmd->add_option("--pvd", o->pvdDir, "also write the ParaView series of frames 1..N into this folder");
  cmd->add_option("--width", o->width, "image width, pixels (default 1000)")->check(CLI::Range(64, 8192));
  cmd->add_option("--height", o->height, "image height, pixels (default 750)")->check(CLI::Range(64, 8192));
  cmd->add_option("--truth-error", o->truthMethod,
                  "also the error view of this method (lit, separable, texture-space, ray-march, parallax) "
                  "against the path-traced truth");
  cmd->add_option("--truth-seconds", o->truthSeconds, "s of path tracing for --truth-error (default 30)")
      ->check(CLI::PositiveNumber);
  cmd->callback([o, &global, &exitCode] {
    exitCode = printRun("inspect", global, studies::inspectRun(*o, dataSceneSettings()));
  });
}

}  // namespace tissue::sim_app
