// tissue-sim sss-bench [--mesh FILE] [--width W --height H] [--frames N] [--samples S] [--out DIR]
// --json: every subsurface-scattering method and setting on one frame of the organ, with its time
// and its image RMS against the CPU reference. The bench and its report are tissue::studies'
// (studies/sss_bench.h); this command makes the context and prints.

#include "tissue/studies/sss_bench.h"
#include "../organ_data.h"
#include "cli_options.h"
#include "command.h"
#include "gl_environment.h"
#include "output.h"
#include "report_output.h"

namespace tissue::sim_app {
namespace {

struct BenchOptions {
  std::string mesh;     // empty: data/meshes/liver.obj
  ReportPlaces places;  // --out: the report (sss_bench.md, .csv, .json)
  studies::SssBenchConfig config;
};

int run(BenchOptions o, const GlobalOptions& global) {
  const char* cmd = "sss-bench";
  auto context = createAppContext({}, false);
  if (!context) return fail(cmd, context.error().message);
  auto renderer = createAppRenderer(**context, o.config.samples, false);
  if (!renderer) return fail(cmd, renderer.error().message);
  o.config.glRenderer = (*context)->info().renderer;
  auto bench = studies::runSssBench(*renderer, organSourceFor(meshOrDefault(o.mesh)), o.config);
  if (!bench) return fail(cmd, bench.error().message);
  return finishStudy(cmd, std::move(bench->output), o.places, global);
}

}  // namespace

void registerSssBenchCommand(CLI::App& app, const GlobalOptions& global, int& exitCode) {
  auto o = std::make_shared<BenchOptions>();
  auto* cmd = app.add_subcommand("sss-bench",
                                 "time SSS methods and measure their image RMS against the CPU reference");
  cmd->add_option("--mesh", o->mesh, "organ mesh with UVs (default data/meshes/liver.obj)");
  addImageSizeOptions(cmd, o->config.width, o->config.height);
  cmd->add_option("--frames", o->config.frames, "timed frames per setting (default 5)");
  cmd->add_option("--samples", o->config.samples, "MSAA samples (default 0 = off)");
  cmd->add_option("--out", o->places.out, "folder for the report: sss_bench.md, .csv, .json (created)");
  cmd->callback([o, &global, &exitCode] { exitCode = run(*o, global); });
}

}  // namespace tissue::sim_app
