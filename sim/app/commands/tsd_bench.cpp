// tissue-sim tsd-bench: Jimenez and Gutierrez 2008 Table 1 on our renderer. 1, 2, 4, 8 and 16
// organ instances in a row by six camera distances; each cell the speed-up of texture-space
// diffusion with the three irradiance-map optimisations over without, and the accuracy rows. The
// bench and its report are tissue::studies' (studies/tsd_bench.h); this command makes the context,
// writes the report and prints.
#include <filesystem>
#include <optional>

#include "cli_options.h"
#include "command.h"
#include "gl_environment.h"
#include "output.h"
#include "report_output.h"
#include "tissue/studies/texture_space_organ.h"
#include "tissue/studies/tsd_bench.h"

namespace tissue::sim_app {
namespace {

struct BenchOptions {
  std::string mesh;
  float scale = 1.0f;   // mm per file unit
  ReportPlaces places;  // --out (report), --chart, --image
  studies::TsdBenchConfig config;
};

int run(BenchOptions o, const GlobalOptions& global) {
  const char* cmd = "tsd-bench";
  const auto meshPath = meshOrDefault(o.mesh);
  auto organ = studies::loadTsdOrgan(meshPath, o.scale);
  if (!organ) return fail(cmd, organ.error().message);
  o.config.skinTable = sharedDir() / "reference" / "deon_skin_gaussians.tsv";
  if (auto g = studies::skinGaussians(o.config.skinTable, o.config.gaussians); !g)
    return fail(cmd, "--gaussians " + std::to_string(o.config.gaussians) + ": " + g.error().message +
                         " (the shared folder: $TISSUE_SHARED_DIR)");
  o.config.mesh = meshPath.string();
  o.config.chart = !o.places.chart.empty();
  o.config.image = !o.places.image.empty();
  std::optional<studies::TsdBenchResult> bench;
  {  // The GL context lives in this scope only: VTK's chart needs its own (GLX) context afterwards.
    auto context = createAppContext({}, false);
    if (!context) return fail(cmd, context.error().message);
    auto renderer = createAppRenderer(**context, 0, false);
    if (!renderer) return fail(cmd, renderer.error().message);
    o.config.glRenderer = (*context)->info().renderer;
    auto r = studies::runTsdBench(*renderer, *organ, o.config);
    if (!r) return fail(cmd, r.error().message);
    bench = std::move(*r);
  }
  return finishStudy(cmd, std::move(bench->output), o.places, global);
}

}  // namespace

void registerTsdBenchCommand(CLI::App& app, const GlobalOptions& global, int& exitCode) {
  auto o = std::make_shared<BenchOptions>();
  auto* cmd = app.add_subcommand("tsd-bench",
                                 "Jimenez et al. 2008 Table 1: speed-up of the optimised texture-space "
                                 "diffusion by organ count and distance");
  cmd->add_option("--mesh", o->mesh, "organ mesh (default data/meshes/liver.obj); no UVs: automatic atlas");
  cmd->add_option("--scale", o->scale, "mm per file unit (default 1)");
  addImageSizeOptions(cmd, o->config.width, o->config.height);
  cmd->add_option("--map-size", o->config.mapSize, "T_max, irradiance map texels (default 256)");
  cmd->add_option("--gaussians", o->config.gaussians, "profile terms: 2, 4 or 6 (default 6)");
  cmd->add_option("--repeats", o->config.repeats, "timed frames per cell and path (default 3; median)");
  cmd->add_option("--out", o->places.out, "folder for the report: tsd_bench.md, .csv, .json (created)");
  cmd->add_option("--chart", o->places.chart, "write the speed-ups as a line chart PNG");
  cmd->add_flag("--accuracy-only", o->config.accuracyOnly, "only the accuracy rows (no speed-up table)");
  cmd->add_option("--image", o->places.image,
                  "write the optimised frame of 16 organs at the second distance");
  cmd->callback([o, &global, &exitCode] { exitCode = run(*o, global); });
}

}  // namespace tissue::sim_app
