// A recorded session re-run through the trainee's loop (replay_run.h).
#include "tissue/studies/replay_run.h"

#include <cstdio>
#include <memory>
#include <optional>

#include "json_text.h"
#include "loop_detail.h"
#include "tissue/core/image.h"
#include "tissue/core/statistics.h"
#include "tissue/inspect/organ_snapshot.h"
#include "tissue/inspect/pvd_series.h"
#include "tissue/scenario/scenario_run.h"
#include "tissue/scene/session.h"
#include "tissue/studies/loop_report.h"

namespace tissue::studies {

Result<std::string> replaySession(const ReplayConfig& o, const scene::SceneSettings& settings) {
  // Setup: the session, and the scenario it was recorded with in a scene (GL with render).
  auto session = scene::loadSession(o.session);
  if (!session) return session.error();
  std::unique_ptr<context::GlContext> context;
  if (o.render) {
    auto made = detail::offscreenContext(settings, o.logContext);  // the scene draws offscreen
    if (!made) return made.error();
    context = std::move(*made);
  }
  scene::SceneSettings sceneSettings = settings;
  sceneSettings.meshWorkFollowsMethod = o.pvdDir.empty();  // the series writes planes and tangents
  auto scene = detail::makeLoopScene(context.get(), sceneSettings);
  if (!scene) return scene.error();
  if (auto added = scene->addOrgan({.scenario = session->scenario, .method = o.method}); !added)
    return added.error();
  const scene::OrganLoop& loop = *scene->loop(0);
  if (auto match = scene::checkSessionMatches(*session, loop); !match) return match.error();

  // The frames, each one pass through the library's loop with the recorded input.
  scene::LoopRecord record;
  Image8 image;
  std::optional<inspect::PvdSeries> pvd;  // issue 15: one .vtp per frame, the .pvd rewritten atomically
  if (!o.pvdDir.empty()) {
    auto series = inspect::PvdSeries::create(o.pvdDir);
    if (!series) return series.error();
    pvd = std::move(*series);
  }
  std::vector<double> meshMs;  // phase 2 as a whole: what the method's mesh work costs
  for (std::size_t i = 0; i < session->frames.size(); ++i) {
    auto f =
        scene->advance(0, scene::sessionInput(*session, i), o.render ? &image : nullptr, o.width, o.height);
    if (!f) return Error{session->file.string() + ": frame " + std::to_string(i) + ": " + f.error().message};
    record.add(*f, loop);
    meshMs.push_back(f->ms.meshMs);
    if (pvd)
      if (auto w = pvd->addFrame(inspect::snapshotOf(loop.run(), loop.surface())); !w) return w.error();
    if (o.render && !o.outDir.empty() && (i + 1) % std::size_t(o.imageEvery) == 0) {
      char name[32];
      std::snprintf(name, sizeof name, "frame_%04zu.png", i + 1);
      if (auto w = writePng(o.outDir / name, image); !w) return w.error();
    }
  }

  // Report: the fingerprint, the frame times and every phase.
  const auto summary = scenario::summarize(record.frames);
  const auto& total = record.phases.phases.back().second;
  nlohmann::json j{{"session", session->file.string()},
                   {"scenario", loop.run().scenario().file.string()},
                   {"frames", session->frames.size()},
                   {"rendered", o.render},
                   {"method", render::shadingMethodName(o.method)},
                   {"plane_refit_frames", record.planeFrames},
                   {"tangent_frames", record.tangentFrames},
                   {"positions_sha256", scene::positionsSha256(loop.geometricPositions())},
                   {"frame_ms", detail::msSummary(total)},
                   {"mesh_ms", detail::msSummary(meshMs)},
                   {"phases_ms", detail::loopPhases(record.phases)},
                   {"max_contact_force_N", threeDigits(summary.maxForceN)},
                   {"divergence_events", summary.divergenceEvents},
                   {"nan_frames", summary.nanFrames}};
  if (!o.outDir.empty()) {
    Report report;
    report.add("frames.csv", scenario::framesCsv(record.frames));
    report.add("report.json", detail::jsonText(j));
    if (auto w = writeReport(o.outDir, report); !w) return w.error();
    j["out"] = o.outDir.string();
  }
  if (pvd) j["pvd"] = pvd->pvdPath().string();
  return j.dump();
}

}  // namespace tissue::studies
