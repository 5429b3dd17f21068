// tissue-sim simulate SCENARIO.json: runs a scenario file (docs/SCENARIOS.md) and writes the
// per-frame metrics (frames.csv), a summary (summary.json), and with --images a render of the
// last frame.
#include <optional>

#include "cli_options.h"
#include "command.h"
#include "gl_environment.h"
#include "organ_data.h"
#include "output.h"
#include "tissue/core/atomic_file.h"
#include "tissue/core/stopwatch.h"
#include "tissue/inspect/pvd_series.h"
#include "tissue/scenario/scenario_run.h"
#include "tissue/studies/scenario_summary.h"

namespace tissue::sim_app {
namespace {

struct SimulateOptions {
  std::string scenario;
  std::string outDir;
  int frames = 0;          ///< 0: the scenario's
  std::string integrator;  ///< empty: the scenario's
  bool images = false;
  std::string pvdDir;  ///< non-empty: the ParaView series of every frame
};

/// Renders the run's current shape, lit (a scene::Scene of the static organ on a headless context).
Result<std::string> renderLastFrame(const scenario::ScenarioRun& run, const std::filesystem::path& png) {
  context::ContextRequest request;  // the scene draws offscreen
  request.width = request.height = 16;
  auto context = createAppContext(request);
  if (!context) return context.error();
  auto scene = scene::Scene::create((*context)->procAddressFunction(), dataSceneSettings());
  if (!scene) return scene.error();
  auto organ =
      scene->addOrgan({.mesh = run.scenario().mesh, .meshScaleToMm = float(run.scenario().meshScaleToMm)});
  if (!organ) return organ.error();
  if (auto shaped = scene->setPositions(*organ, run.positions()); !shaped) return shaped.error();
  if (auto ok = scene->renderPng(png, 960, 720); !ok) return ok.error();
  return png.filename().string();
}

int runSimulate(const SimulateOptions& o, const GlobalOptions& global) {
  auto parsed = loadScenarioFile("simulate", o.scenario);
  if (!parsed) return fail("simulate", parsed.error().message);
  if (o.frames > 0) parsed->frames = o.frames;
  if (!o.integrator.empty()) {
    const auto integrator = parseIntegratorOption("--integrator", o.integrator);
    if (!integrator) return fail("simulate", integrator.error().message);
    parsed->integrator = *integrator;
  }
  auto run = scenario::ScenarioRun::create(*parsed);
  if (!run) return fail("simulate", run.error().message);
  const std::filesystem::path out =
      o.outDir.empty() ? std::filesystem::path("out") / std::filesystem::path(o.scenario).stem()
                       : std::filesystem::path(o.outDir);

  Stopwatch wall;
  std::vector<scenario::FrameMetrics> frames;
  frames.reserve(static_cast<std::size_t>(parsed->frames));
  std::optional<inspect::RunSeries> pvd;
  if (!o.pvdDir.empty()) {
    auto series = inspect::RunSeries::create(**run, o.pvdDir);
    if (!series) return fail("simulate", series.error().message);
    pvd = std::move(*series);
  }
  for (int f = 0; f < parsed->frames; ++f) {
    auto m = (*run)->advance();
    if (!m) return fail("simulate", m.error().message);
    frames.push_back(*m);
    if (pvd)
      if (auto w = pvd->addFrame(**run); !w) return fail("simulate", w.error().message);
  }
  auto summary = nlohmann::json::parse(studies::scenarioRunSummaryJson(**run, frames, wall.elapsedMs()));
  if (auto ok = writeTextFileAtomic(out / "frames.csv", scenario::framesCsv(frames)); !ok)
    return fail("simulate", ok.error().message);
  summary["frames_csv"] = (out / "frames.csv").string();
  if (pvd) summary["pvd"] = pvd->series().pvdPath().string();
  if (o.images) {
    auto image = renderLastFrame(**run, out / "last_frame.png");
    if (image)
      summary["image"] = (out / *image).string();
    else
      summary["image_skipped"] = image.error().message;
  }
  if (auto ok = writeTextFileAtomic(out / "summary.json", summary.dump(2) + "\n"); !ok)
    return fail("simulate", ok.error().message);
  printResult(global, summary);
  return summary["nan_frames"].get<long>() == 0 ? 0
                                                : fail("simulate", "some frames held NaN; see frames.csv");
}

}  // namespace

void registerSimulateCommand(CLI::App& app, const GlobalOptions& global, int& exitCode) {
  auto o = std::make_shared<SimulateOptions>();
  auto* cmd = app.add_subcommand("simulate",
                                 "run a scenario file; write per-frame metrics (frames.csv) and a summary");
  cmd->add_option("scenario", o->scenario, "scenario file (JSON, docs/SCENARIOS.md)")->required();
  cmd->add_option("--out", o->outDir, "output folder (default out/<scenario name>)");
  cmd->add_option("--frames", o->frames, "frames to run instead of the scenario's");
  cmd->add_option("--integrator", o->integrator, "integrator instead of the scenario's (to compare them)");
  cmd->add_option("--pvd", o->pvdDir,
                  "write the ParaView series (.pvd, one file per frame) into this folder");
  cmd->add_flag("--images", o->images, "also render the last frame (needs UVs and a material file)");
  cmd->callback([o, &global, &exitCode] { exitCode = runSimulate(*o, global); });
}

}  // namespace tissue::sim_app
