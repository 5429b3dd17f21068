// tissue-sim inspect's run (inspect_run.h).
#include "tissue/studies/inspect_run.h"

#include <cmath>
#include <limits>
#include <memory>
#include <optional>

#include "json_text.h"
#include "loop_detail.h"
#include "tissue/core/atomic_file.h"
#include "tissue/core/stopwatch.h"
#include "tissue/inspect/inspection_views.h"
#include "tissue/inspect/organ_snapshot.h"
#include "tissue/inspect/pvd_series.h"
#include "tissue/scenario/scenario_run.h"
#include "tissue/scene/organ_methods.h"
#include "tissue/scene/session.h"
#include "tissue/scene/truth_view.h"
#include "tissue/studies/atlas.h"
#include "tissue/studies/frame_radiance.h"
#include "tissue/studies/loop_report.h"

namespace tissue::studies {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

/// The truth_error view's map and its report: the organ drawn with `method` by `scene` (its
/// framing camera, no instrument: the truth has none) against the truth of the same frame.
Result<std::pair<inspect::TruthErrorMap, nlohmann::json>> truthErrorOf(scene::Scene& scene,
                                                                       const inspect::OrganSnapshot& frame,
                                                                       render::ShadingMethod method,
                                                                       const InspectConfig& o) {
  const int w = o.truthWidth, h = o.truthHeight;
  if (auto set = scene.setMethod(0, method); !set) return set.error();
  scene.setInstrumentVisible(false);
  if (auto image = scene.renderImage(w, h); !image) return image.error();
  auto linear = lastFrameRadiance(scene.renderer());
  if (!linear) return linear.error();
  truth::PathTraceSettings ts;
  ts.width = w;
  ts.height = h;
  ts.samplesPerPass = 4;
  ts.passes = 4096;  // until the time is up
  ts.threads = o.threads;
  ts.seed = 13;
  ts.onPass = [budget = o.truthSeconds](const truth::PathTraceProgress& p) { return p.seconds < budget; };
  auto T = scene::renderTruth(scene, 0, ts);
  if (!T) return T.error();
  auto rays = truth::makeRayMesh(frame.render.positions, frame.render.triangles);
  if (!rays) return rays.error();
  const auto error = relativeErrorImage(*linear, T->radiance, T->covered, w, h);
  inspect::TruthErrorMap map{
      .perRenderVertex = pixelValuesAtVertices(scene.camera(), w, h, error, frame.render.positions, **rays),
      .quantity = std::string(render::shadingMethodName(method)) + " error",
      .unit = "|M - T| / RMS(T)"};
  std::size_t visible = 0;
  for (float v : map.perRenderVertex)
    visible += std::isfinite(v) ? 1 : 0;
  const AtlasScore score = scoreAgainstTruth(T->radiance, *linear, T->covered);
  nlohmann::json report{{"method", std::string(render::shadingMethodName(method))},
                        {"width", w},
                        {"height", h},
                        {"truth_spp", T->samplesPerPixel},
                        {"truth_s", threeDigits(T->seconds)},
                        {"rel_rms", threeDigits(score.relRms)},
                        {"noise_rel_rms", threeDigits(truthNoiseRelRms(*T))},
                        {"visible_vertices", visible}};
  return std::pair{std::move(map), std::move(report)};
}

}  // namespace

std::vector<float> pixelValuesAtVertices(const render::Camera& camera, int width, int height,
                                         std::span<const float> perPixel, std::span<const Float3> positionsMm,
                                         const truth::RayMesh& rays) {
  // The pinhole of render::Camera: forward f, right r = f x up, up' = r x f; a point at depth z
  // along f lands at x_ndc = (d.r) / (z tan(fov/2) aspect), y_ndc = (d.u) / (z tan(fov/2)).
  const Float3 f = normalize(camera.target - camera.eye);
  const Float3 r = normalize(cross(f, camera.up));
  const Float3 u = cross(r, f);
  const float tanHalf = std::tan(0.5f * camera.verticalFovDeg * 3.14159265f / 180.0f);
  const float aspect = float(width) / float(height);
  std::vector<float> out(positionsMm.size(), kNaN);
  for (std::size_t i = 0; i < positionsMm.size(); ++i) {
    const Float3 d = positionsMm[i] - camera.eye;
    const float z = dot(d, f);
    if (!(z > 0.0f)) continue;
    const float x = dot(d, r) / (z * tanHalf * aspect), y = dot(d, u) / (z * tanHalf);
    const int col = int(std::floor(0.5f * (x + 1.0f) * float(width)));
    const int row = int(std::floor(0.5f * (1.0f - y) * float(height)));
    if (col < 0 || col >= width || row < 0 || row >= height) continue;
    // Visible: nothing nearer along the eye ray than just short of the vertex itself.
    const float dist = length(d);
    const std::array<double, 3> origin{camera.eye.x, camera.eye.y, camera.eye.z};
    const std::array<double, 3> dir{d.x / dist, d.y / dist, d.z / dist};
    if (rays.intersect(origin, dir, 0.0, double(dist) * (1.0 - 1e-4) - 1e-3)) continue;
    out[i] = perPixel[std::size_t(row) * std::size_t(width) + std::size_t(col)];
  }
  return out;
}

std::vector<float> relativeErrorImage(std::span<const Float3> method, std::span<const Float3> truth,
                                      std::span<const std::uint8_t> covered, int width, int height) {
  const std::size_t n = std::size_t(width) * std::size_t(height);
  double sumT2 = 0.0;
  std::size_t count = 0;
  for (std::size_t i = 0; i < n; ++i)
    if (covered[i]) {
      sumT2 += double(dot(truth[i], truth[i]));
      ++count;
    }
  std::vector<float> raw(n, kNaN), out(n, kNaN);
  if (count == 0 || !(sumT2 > 0.0)) return out;
  const float rms = float(std::sqrt(sumT2 / double(count)));
  for (std::size_t i = 0; i < n; ++i)
    if (covered[i]) raw[i] = length(method[i] - truth[i]) / rms;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      if (!covered[std::size_t(y) * std::size_t(width) + std::size_t(x)]) continue;
      float sum = 0.0f;
      int k = 0;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int xx = x + dx, yy = y + dy;
          if (xx < 0 || yy < 0 || xx >= width || yy >= height) continue;
          const float v = raw[std::size_t(yy) * std::size_t(width) + std::size_t(xx)];
          if (std::isfinite(v)) sum += v, ++k;
        }
      out[std::size_t(y) * std::size_t(width) + std::size_t(x)] = sum / float(k);
    }
  return out;
}

Result<std::string> inspectRun(const InspectConfig& o, scene::SceneSettings settings) {
  // A session names its scenario and gives each frame's input; a scenario runs its own script.
  const std::string input = o.input.string();
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
  // The simulation only (the views are VTK's), unless the truth view needs the method drawn.
  std::optional<render::ShadingMethod> truthMethod;
  if (!o.truthMethod.empty()) {
    auto m = scene::parseShadingMethod(o.truthMethod);
    if (!m) return Error{"--truth-error: " + m.error().message};
    truthMethod = *m;
  }
  std::unique_ptr<context::GlContext> context;
  if (truthMethod) {
    auto offscreen = detail::offscreenContext(settings, true);
    if (!offscreen) return offscreen.error();
    context = std::move(*offscreen);
  }
  scene::SceneSettings sceneSettings = settings;
  sceneSettings.meshWorkFollowsMethod = false;  // the snapshots read every attribute
  auto made = detail::makeLoopScene(context.get(), sceneSettings);
  if (!made) return made.error();
  auto scene = std::make_optional(std::move(*made));
  if (auto added = scene->addOrgan({.scenario = scenarioFile}); !added) return added.error();
  const scene::OrganLoop& loop = *scene->loop(0);
  if (session)
    if (auto match = scene::checkSessionMatches(*session, loop); !match) return match.error();
  const long last = session ? long(session->frames.size()) : long(loop.run().scenario().frames);
  const long frame = o.frame < 0 ? last : o.frame;
  if (frame > last)
    return Error{input + ": --frame " + std::to_string(frame) + " is past the end (" + std::to_string(last) +
                 " frames); pass --frame 0.." + std::to_string(last)};

  // Run to the frame (with a series, each frame into it), then write every view of it.
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
    if (!f) return Error{input + ": frame " + std::to_string(i) + ": " + f.error().message};
    if (!series) continue;
    Stopwatch snap;
    const auto snapshot = inspect::snapshotOf(loop.run(), loop.surface());
    snapshotMs.push_back(snap.elapsedMs());
    auto cost = series->addFrame(snapshot);
    if (!cost) return cost.error();
    frameMs.push_back(cost->frameMs);
    collectionMs.push_back(cost->collectionMs);
  }
  const auto snapshot = inspect::snapshotOf(loop.run(), loop.surface());
  std::optional<std::pair<inspect::TruthErrorMap, nlohmann::json>> truthError;
  if (truthMethod) {
    auto error = truthErrorOf(*scene, snapshot, *truthMethod, o);
    if (!error) return Error{input + ": --truth-error " + o.truthMethod + ": " + error.error().message};
    truthError = std::move(*error);
  }
  // VTK draws through GLX on this thread: the scene's EGL or OSMesa context goes first (a GLX
  // make-current while another API's context is current fails with BadAccess).
  scene.reset();
  context.reset();
  auto views = inspect::writeInspectionViews(snapshot, o.outDir, {.widthPx = o.width, .heightPx = o.height},
                                             truthError ? &truthError->first : nullptr);
  if (!views) return views.error();
  nlohmann::json list = nlohmann::json::array();
  for (const auto& v : *views)
    list.push_back({{"view", v.name},
                    {"png", v.png.string()},
                    {"vtp", v.data.string()},
                    {"render_ms", threeDigits(v.renderMs)},
                    {"write_ms", threeDigits(v.writeMs)}});
  nlohmann::json report{{"input", input}, {"frame", frame}, {"out", o.outDir.string()}, {"views", list}};
  if (series)
    report["pvd"] = {{"file", series->pvdPath().string()},
                     {"frames", series->frameCount()},
                     {"snapshot_ms", detail::msSummary(snapshotMs)},
                     {"frame_file_ms", detail::msSummary(frameMs)},
                     {"collection_ms", detail::msSummary(collectionMs)}};
  if (truthError) report["truth_error"] = truthError->second;
  return detail::jsonText(report);
}

}  // namespace tissue::studies
