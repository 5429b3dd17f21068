// tissue-sim inspect SCENARIO_OR_SESSION [--frame N] --out DIR [--pvd DIR]: runs a scenario (or
// replays a recorded session) to frame N through the library's loop and writes the VTK inspection
// views of that frame (PNG with colour bars, and a .vtp each; tissue/inspect/inspection_views.h);
// with --pvd also the ParaView series of frames 1..N (tissue/inspect/pvd_series.h) and its cost.
#include "command.h"
#include "organ_data.h"
#include "output.h"
#include "tissue/core/atomic_file.h"
#include "tissue/core/statistics.h"
#include "tissue/core/stopwatch.h"
#include "tissue/inspect/inspection_views.h"
#include "tissue/inspect/pvd_series.h"
#include "tissue/scenario/scenario_run.h"
#include "tissue/scene/session.h"
#include "tissue/studies/loop_report.h"

namespace tissue::sim_app {
namespace {

struct InspectOptions {
  std::string input;
  long frame = -1;  ///< -1: the scenario's last frame (a session's last)
  std::filesystem::path outDir;
  std::filesystem::path pvdDir;  ///< empty: no series
  int width = 1000, height = 750;
};

Result<nlohmann::json> inspect(const InspectOptions& o) {
  // A session names its scenario and gives each frame's input; a scenario runs its own script.
  auto text = readTextFile(o.input);
  if (!text) return text.error();
  std::optional<scene::Session> session;
  std::filesystem::path scenarioFile = o.input;
  if (text->find("\"tissue-session\"") != std::string::npos) {
    auto loaded = scene::loadSession(o.input);
    if (!loaded) return loaded.error();
    session = std::move(*loaded);
    scenarioFile = session->scenario;
  }
  scene::SceneSettings settings = dataSceneSettings();
  settings.gl = false;  // the simulation only: the views are VTK's
  auto scene = scene::Scene::create({}, settings);
  if (!scene) return scene.error();
  if (auto added = scene->addOrgan({.scenario = scenarioFile}); !added) return added.error();
  const scene::OrganLoop& loop = *scene->loop(0);
  if (session)
    if (auto match = scene::checkSessionMatches(*session, loop); !match) return match.error();
  const long last = session ? long(session->frames.size()) : long(loop.run().scenario().frames);
  const long frame = o.frame < 0 ? last : o.frame;
  if (frame > last)
    return Error{o.input + ": --frame " + std::to_string(frame) + " is past the end (" +
                 std::to_string(last) + " frames); pass --frame 0.." + std::to_string(last)};

  // Run to the frame (with --pvd, each frame into the series), then write every view of it.
  std::optional<inspect::PvdSeries> series;
  if (!o.pvdDir.empty()) {
    auto created = inspect::PvdSeries::create(o.pvdDir);
    if (!created) return created.error();
    series = std::move(*created);
  }
  std::vector<double> snapshotMs, frameMs, collectionMs;
  for (long i = 0; i < frame; ++i) {
    auto f =
        scene->advance(0, session ? scene::sessionInput(*session, std::size_t(i)) : scene::InstrumentInput{});
    if (!f) return Error{o.input + ": frame " + std::to_string(i) + ": " + f.error().message};
    if (!series) continue;
    Stopwatch snap;
    const auto snapshot = inspect::snapshotOf(loop.run(), loop.surface());
    snapshotMs.push_back(snap.elapsedMs());
    auto cost = series->addFrame(snapshot);
    if (!cost) return cost.error();
    frameMs.push_back(cost->frameMs);
    collectionMs.push_back(cost->collectionMs);
  }
  auto views = inspect::writeInspectionViews(inspect::snapshotOf(loop.run(), loop.surface()), o.outDir,
                                             {.widthPx = o.width, .heightPx = o.height});
  if (!views) return views.error();
  nlohmann::json list = nlohmann::json::array();
  for (const auto& v : *views)
    list.push_back({{"view", v.name},
                    {"png", v.png.string()},
                    {"vtp", v.data.string()},
                    {"render_ms", studies::threeDigits(v.renderMs)},
                    {"write_ms", studies::threeDigits(v.writeMs)}});
  nlohmann::json report{{"input", o.input}, {"frame", frame}, {"out", o.outDir.string()}, {"views", list}};
  if (series) {
    const auto ms = [](const std::vector<double>& samples) {
      const auto s = summarizeSamples(samples);
      return nlohmann::json{{"median", studies::threeDigits(s.median)},
                            {"p99", studies::threeDigits(s.p99)},
                            {"max", studies::threeDigits(s.max)}};
    };
    report["pvd"] = {{"file", series->pvdPath().string()},
                     {"frames", series->frameCount()},
                     {"snapshot_ms", ms(snapshotMs)},
                     {"frame_file_ms", ms(frameMs)},
                     {"collection_ms", ms(collectionMs)}};
  }
  return report;
}

}  // namespace

void registerInspectCommand(CLI::App& app, const GlobalOptions& global, int& exitCode) {
  auto o = std::make_shared<InspectOptions>();
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
  cmd->callback([o, &global, &exitCode] {
    auto report = inspect(*o);
    if (!report) {
      exitCode = fail("inspect", report.error().message);
      return;
    }
    printResult(global, *report);
  });
}

}  // namespace tissue::sim_app
