// tissue-viewer: the interactive viewer. Orbit (left drag), zoom (scroll), poke (right button);
// Esc quits, R resets, N toggles normal mapping, M switches the shading method.
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
  // The project's data folders: $TISSUE_DATA_DIR / $TISSUE_GENERATED_DATA_DIR, else this build's.
  options.folders.data = fromEnv("TISSUE_DATA_DIR", TISSUE_VIEWER_DATA_DIR);
  options.folders.generated = fromEnv("TISSUE_GENERATED_DATA_DIR", TISSUE_VIEWER_GENERATED_DATA_DIR);
  options.mesh = options.folders.data / "meshes" / "liver.obj";

  CLI::App app{
      "tissue-viewer: orbit (left drag), zoom (scroll) and poke (right button) a deforming organ. "
      "Keys: Esc quits, R resets, N toggles normal mapping, M switches the shading method."};
  app.add_option("--mesh", options.mesh, "mesh file with UVs (OBJ, PLY, OFF, STL; mm)");
  app.add_option("--width", options.width, "window width, pixels")->check(CLI::Range(16, 8192));
  app.add_option("--height", options.height, "window height, pixels")->check(CLI::Range(16, 8192));
  app.add_option("--frames", options.frames, "run this many frames, then exit (0: until closed)")
      ->check(CLI::Range(0L, 1000000000L));
  app.add_option("--screenshot", options.screenshot, "write the last frame (offscreen, window size) as PNG");
  app.add_flag("--poke-script", options.pokeScript, "poke the top of the organ automatically (no mouse)");
  app.add_option("--method", options.method,
                 "shading method at start: lit, separable, texture-space or parallax (M cycles; default lit)")
      ->check(CLI::IsMember({"lit", "separable", "texture-space", "parallax"}));
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
