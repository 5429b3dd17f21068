// tissue-sim atlas [--out DIR] [--quick] [--width W --height H] [--spp N] [--truth-seconds S]
// [--cache DIR] --json: every shading method and setting on five frames of the liver (at rest,
// poked by the scenario, a close-up, a grazing view, a thin part lit from behind), each scored
// against the path-traced truth of the same frame. The atlas and its report are tissue::studies'
// (studies/atlas.h); this command makes the context and prints.

#include <cstdio>

#include "../organ_data.h"
#include "command.h"
#include "gl_environment.h"
#include "output.h"
#include "report_output.h"
#include "tissue/studies/atlas.h"

namespace tissue::sim_app {
namespace {

struct AtlasOptions {
  ReportPlaces places;  // --out: atlas.md, .csv, .json, the charts and images
  std::string cache;    // --cache: the truth images; default <out>/truth_cache
  studies::AtlasConfig config;
};

// The atlas on its own context and renderer, both gone before the report is written: VTK's
// charts make a GLX context current, which Mesa refuses (BadAccess) while this thread holds one.
Result<studies::AtlasResult> runOnOwnContext(studies::AtlasConfig config) {
  auto context = createAppContext({}, false);
  if (!context) return context.error();
  auto renderer = render::Renderer::create((*context)->procAddressFunction(),
                                           {.shaders = shaderSettingsFromEnvironment(), .samples = 0});
  if (!renderer) return renderer.error();
  config.glRenderer = (*context)->info().renderer;
  return studies::runAtlas(*renderer, config);
}

int run(AtlasOptions o, const GlobalOptions& global) {
  const char* cmd = "atlas";
  o.config.scene = dataSceneSettings();
  o.config.organ.scenario = dataDir() / "scenarios" / "liver_poke_grasp.json";
  o.config.cacheDir = !o.cache.empty()        ? std::filesystem::path(o.cache)
                      : !o.places.out.empty() ? std::filesystem::path(o.places.out) / "truth_cache"
                                              : std::filesystem::path{};
  o.config.onProgress = [](const std::string& line) { std::fprintf(stderr, "atlas: %s\n", line.c_str()); };
  auto atlas = runOnOwnContext(o.config);
  if (!atlas) return fail(cmd, atlas.error().message);
  return finishStudy(cmd, std::move(atlas->output), o.places, global);
}

}  // namespace

void registerAtlasCommand(CLI::App& app, const GlobalOptions& global, int& exitCode) {
  auto o = std::make_shared<AtlasOptions>();
  auto* cmd =
      app.add_subcommand("atlas", "score every shading method and setting against the path-traced truth");
  cmd->add_option("--out", o->places.out,
                  "folder for the report: atlas.md, .csv, .json, charts, images (created)");
  cmd->add_flag("--quick", o->config.quick,
                "small images, fewer settings and truth samples (about a minute)");
  cmd->add_option("--width", o->config.width, "image width, pixels (default 160; quick 96)");
  cmd->add_option("--height", o->config.height, "image height, pixels (default 120; quick 72)");
  cmd->add_option("--spp", o->config.truthSpp, "truth samples per pixel at most (default 256; quick 64)");
  cmd->add_option("--truth-seconds", o->config.truthSeconds,
                  "truth time per frame at most, s (default 120; quick at most 5)");
  cmd->add_option("--frames", o->config.frames, "timed frames per setting (default 3; quick at most 2)");
  cmd->add_option("--cache", o->cache, "folder of cached truth images (default <out>/truth_cache)");
  cmd->add_flag("--artist-terms", o->config.artistTerms,
                "score with the ambient fill light and the normal maps, which the truth lacks (default off)");
  cmd->callback([o, &global, &exitCode] { exitCode = run(*o, global); });
}

}  // namespace tissue::sim_app
