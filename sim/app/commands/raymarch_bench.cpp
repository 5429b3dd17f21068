// tissue-sim raymarch-bench: the render pipeline's ray-march method at 10, 25, 50 and 100
// samples and adaptive, each timed (its "ray-march" pass) and compared with the CPU reference
// (mesh mode, many samples), after François et al. 2006 Table 2; also the error of the plane
// approximation and the agreement of the method with its CPU twin. The bench and its report are
// tissue::studies' (studies/raymarch_bench.h); this command makes the context and prints.
#include <optional>

#include "../organ_data.h"
#include "cli_options.h"
#include "command.h"
#include "gl_environment.h"
#include "output.h"
#include "report_output.h"
#include "tissue/studies/raymarch_bench.h"

namespace tissue::sim_app {
namespace {

struct BenchOptions {
  std::string mesh;
  ReportPlaces places;  // --out (report and images), --images, --chart
  studies::RayMarchBenchConfig config;
};

int run(BenchOptions o, const GlobalOptions& global) {
  const char* cmd = "raymarch-bench";
  o.config.images = !o.places.out.empty() || !o.places.images.empty();
  o.config.chart = !o.places.chart.empty();
  std::optional<studies::RayMarchBenchResult> bench;
  {  // Release GL before charting: VTK draws through GLX, which refuses to share the process's
     // current EGL context (X error BadAccess on glXMakeCurrent, Mesa 22.3).
    auto context = createAppContext({}, false);
    if (!context) return fail(cmd, context.error().message);
    o.config.glRenderer = (*context)->info().renderer;
    auto r = studies::runRayMarchBench((*context)->procAddressFunction(),
                                       {.shaders = shaderSettingsFromEnvironment()},
                                       organSourceFor(meshOrDefault(o.mesh)), o.config);
    if (!r) return fail(cmd, r.error().message);
    bench = std::move(*r);
  }
  return finishStudy(cmd, std::move(bench->output), o.places, global);
}

}  // namespace

void registerRayMarchBenchCommand(CLI::App& app, const GlobalOptions& global, int& exitCode) {
  auto o = std::make_shared<BenchOptions>();
  studies::RayMarchBenchConfig& c = o->config;
  auto* cmd = app.add_subcommand("raymarch-bench",
                                 "time ray-marched subsurface scattering per sample count and adaptive, "
                                 "with the error against the CPU reference");
  cmd->add_option("--mesh", o->mesh, "a data/ mesh with a material file (default data/meshes/liver.obj)");
  addImageSizeOptions(cmd, c.width, c.height);
  cmd->add_option("--reference-samples", c.referenceSamples, "CPU reference samples (default 200)");
  cmd->add_option("--repeats", c.repeats, "timed frames per setting, median (default 7)");
  cmd->add_option("--poke-depth", c.pokeDepthMm, "poke depth, mm (default 8; 0 = rest shape)");
  cmd->add_flag("!--whole", c.closeUp, "frame the whole organ instead of a close-up of the poke site");
  cmd->add_option("--depth-resolution", c.adaptive.depthResolutionMm,
                  "adaptive: wanted depth step, mm (default 0.06)");
  cmd->add_option("--texels-per-step", c.adaptive.texelsPerStep,
                  "adaptive: wanted sideways step, texels or pixels (default 1.5)");
  cmd->add_option("--cutoff", c.adaptive.cutoff,
                  "adaptive: round-trip transmittance where the march stops (default 0.03)");
  cmd->add_option("--min-samples", c.adaptive.minSamples, "adaptive: fewest samples (default 4)");
  cmd->add_option("--chart", o->places.chart, "PNG chart of error against frame time");
  cmd->add_option("--images", o->places.images, "folder for the images (raymarch_*.png; created)");
  cmd->add_option("--out", o->places.out,
                  "folder for the report: raymarch_bench.md, .csv, .json and the images");
  cmd->callback([o, &global, &exitCode] { exitCode = run(*o, global); });
}

}  // namespace tissue::sim_app
