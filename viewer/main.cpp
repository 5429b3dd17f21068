// tissue-viewer: the interactive viewer. The simulator moves the organ (the scenario's
// mass-spring model through scene::OrganLoop); orbit (left drag), zoom (scroll), poke with the
// instrument (right button; scroll with it held, Shift+scroll, W/S or PageUp/PageDown move it in
// depth), G grasps and releases; Esc quits, C resets the view, R records, N toggles normal
// mapping, M switches the shading method, I opens a VTK inspection window of the frame (or writes
// the views without a display); the panel shows the figures and switches the rest.
#include <CLI/CLI.hpp>
#include <cstdlib>
#include <exception>
#include <iostream>

#include "viewer_app.h"

namespace {

std::filesystem::path fromEnv(const char* name, const char* fallback) {
  if (const char* value = std::getenv(name); value && *value) return value;
  return fallback;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace tissue::viewer;
  ViewerOptions options;
  // The project's data folders: $TISSUE_DATA_DIR / $TISSUE_GENERATED_DATA_DIR / $TISSUE_SHARED_DIR,
  // else this build's.
  options.folders.data = fromEnv("TISSUE_DATA_DIR", TISSUE_VIEWER_DATA_DIR);
  options.folders.generated = fromEnv("TISSUE_GENERATED_DATA_DIR", TISSUE_VIEWER_GENERATED_DATA_DIR);
  options.folders.shared = fromEnv("TISSUE_SHARED_DIR", TISSUE_VIEWER_SHARED_DIR);
  options.scenario = options.folders.data / "scenarios" / "liver_poke_grasp.json";

  CLI::App app{
      "tissue-viewer: the simulated organ, poked and grasped with the scenario's instrument. Mouse: orbit "
      "(left drag), zoom (scroll), poke (right button; with it held, scroll moves the tool in depth). Keys: "
      "W/S or PageDown/PageUp depth, G grasp/release, M method, N normal map, C home view, R record, I "
      "inspection views, Esc quit."};
  app.add_option("--scenario", options.scenario,
                 "scenario file (default data/scenarios/liver_poke_grasp.json)");
  app.add_option("--width", options.width, "window width, pixels")->check(CLI::Range(16, 8192));
  app.add_option("--height", options.height, "window height, pixels")->check(CLI::Range(16, 8192));
  app.add_option("--frames", options.frames, "run this many frames, then exit (0: until closed)")
      ->check(CLI::Range(0L, 1000000000L));
  app.add_option("--screenshot", options.screenshot,
                 "write the last frame of a --frames or --replay run (the window, panel included) as PNG");
  app.add_flag("--poke-script,--script", options.pokeScript,
               "no input: the scenario's own instrument path and grasps drive the loop");
  app.add_option(
         "--method", options.method,
         "shading method at start: lit, separable, texture-space, ray-march or parallax (default lit)")
      ->check(CLI::IsMember({"lit", "separable", "texture-space", "ray-march", "parallax"}));
  app.add_option("--record", options.record,
                 "record the session (pose, grasp, camera, method) into this file");
  app.add_option("--replay", options.replay, "drive the viewer by a recorded session (data/sessions/*.json)");
  app.add_option("--log", options.log, "write one CSV line per frame: phase ms, force N, grasp");
  app.add_option("--budget-ms", options.budgetMs,
                 "start under this frame budget, ms: the quality controller chooses the organ's method and "
                 "setting (0: off; the panel's slider changes it)")
      ->check(CLI::Range(0.0, 1e6));
  app.get_option("--replay")->excludes("--poke-script")->excludes("--record");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help
    std::cerr << "tissue-viewer: " << e.what() << "; run 'tissue-viewer --help' for usage" << std::endl;
    return 2;
  }
  try {
    if (auto ok = runViewer(options); !ok) {
      std::cerr << "tissue-viewer: " << ok.error().message << std::endl;
      return 1;
    }
  } catch (const std::exception& e) {
    std::cerr << "tissue-viewer: unexpected error: " << e.what() << std::endl;
    return 1;
  }
  return 0;
}
