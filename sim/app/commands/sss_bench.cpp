// tissue-sim sss-bench [--mesh FILE] [--width W --height H] [--frames N] [--samples S] --json: every
// subsurface-scattering method and setting on one frame of the organ, with its time and its
// image RMS against the CPU reference (the exact screen-space convolution with the material's
// dipole profile, tissue::reference). The bench is tissue::studies' (studies/sss_bench.h).
#include <filesystem>

#include "../organ_data.h"
#include "command.h"
#include "gl_environment.h"
#include "output.h"
#include "tissue/context/headless_context.h"
#include "tissue/core/vec_math.h"
#include "tissue/studies/sss_bench.h"

namespace tissue::sim_app {
namespace {

struct BenchOptions {
  std::string mesh = (dataDir() / "meshes" / "liver.obj").string();
  int width = 320;   // pixels
  int height = 240;  // pixels
  int frames = 5;
  int samples = 0;  // MSAA
};

int run(const BenchOptions& o, const GlobalOptions& global) {
  const char* cmd = "sss-bench";
  if (o.width <= 0 || o.height <= 0 || o.frames <= 0)
    return fail(cmd, "--width, --height and --frames must be positive");
  studies::SssBenchContext ctx;
  ctx.width = o.width;
  ctx.height = o.height;
  ctx.frames = o.frames;
  // The organ with its own UVs and its data/materials/<stem>.json (scene::loadOrganAssets).
  scene::OrganSource source = organSourceFor(o.mesh);
  source.uvAtlasFallback = false;
  auto organ = scene::loadOrganAssets(source);
  if (!organ) {
    if (!std::filesystem::is_regular_file(source.material))
      return fail(cmd, "material for " + o.mesh + ": " + organ.error().message);
    return fail(cmd, o.mesh + ": " + organ.error().message);
  }
  auto context = createAppContext({}, false);
  if (!context) return fail(cmd, context.error().message);
  render::RendererSettings settings;
  settings.samples = o.samples;
  settings.shaders = shaderSettingsFromEnvironment();
  auto renderer = render::Renderer::create((*context)->procAddressFunction(), settings);
  if (!renderer) return fail(cmd, renderer.error().message);
  ctx.renderer = &*renderer;
  if (auto r = studies::setUpSssBench(ctx, *organ); !r) return fail(cmd, o.mesh + ": " + r.error().message);
  nlohmann::json results = nlohmann::json::array(), skipped = nlohmann::json::array();
  std::vector<studies::SssBenchSkip> skips;
  for (const studies::SssBenchMethod& method : studies::kSssBenchMethods) {
    auto rows = method.rows(ctx, skips);
    if (!rows) return fail(cmd, std::string(method.name) + ": " + rows.error().message);
    for (const studies::SssBenchRow& r : *rows) {
      results.push_back({{"method", r.method},
                         {"setting", r.setting},
                         {"ms", r.ms},
                         {"method_ms", r.methodMs},
                         {"image_rms", r.imageRms},
                         {"relative_rms", r.relativeRms}});
    }
  }
  for (const auto& skip : skips)
    skipped.push_back({{"method", skip.method}, {"setting", skip.setting}, {"reason", skip.reason}});
  nlohmann::json out;
  out["mesh"] = o.mesh;
  out["material"] = ctx.material.name;
  out["width"] = o.width;
  out["height"] = o.height;
  out["frames"] = o.frames;
  out["samples"] = o.samples;
  out["gl_renderer"] = (*context)->info().renderer;
  out["reference"] = "exact screen-space convolution with the normalised dipole profile (tissue::reference)";
  out["results"] = results;
  out["skipped"] = skipped;
  printResult(global, out);
  return 0;
}

}  // namespace

void registerSssBenchCommand(CLI::App& app, const GlobalOptions& global, int& exitCode) {
  auto opts = std::make_shared<BenchOptions>();
  auto* cmd = app.add_subcommand("sss-bench",
                                 "time SSS methods and measure their image RMS against the CPU reference");
  cmd->add_option("--mesh", opts->mesh, "organ mesh with UVs (default data/meshes/liver.obj)");
  cmd->add_option("--width", opts->width, "image width, pixels (default 320)");
  cmd->add_option("--height", opts->height, "image height, pixels (default 240)");
  cmd->add_option("--frames", opts->frames, "timed frames per setting (default 5)");
  cmd->add_option("--samples", opts->samples, "MSAA samples (default 0 = off)");
  cmd->callback([opts, &global, &exitCode] { exitCode = run(*opts, global); });
}

}  // namespace tissue::sim_app
