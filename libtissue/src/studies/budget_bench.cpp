// The budget bench (budget_bench.h): the scene of organs, the session's poke as recorded shapes,
// the fixed settings and the controller under each budget, scored against one path-traced truth.
#include "tissue/studies/budget_bench.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <tuple>

#include "atlas_detail.h"
#include "budget_bench_pixels.h"
#include "json_text.h"
#include "tissue/core/stopwatch.h"
#include "tissue/scene/session.h"
#include "tissue/scene/truth_view.h"
#include "tissue/studies/atlas.h"
#include "tissue/studies/frame_radiance.h"

namespace tissue::studies {
namespace {

Mat4 placed(Float3 t, float rotZDeg) {
  const float a = rotZDeg * 3.14159265f / 180.0f;
  Mat4 m = kIdentity4;
  m[0] = std::cos(a), m[1] = std::sin(a), m[4] = -std::sin(a), m[5] = std::cos(a);
  m[12] = t.x, m[13] = t.y, m[14] = t.z;
  return m;
}

// The laparoscope: looking down into the field at about 40 degrees.
render::Camera benchCamera() {
  render::Camera c;
  c.eye = {0.0f, -300.0f, 260.0f};
  c.target = {0.0f, 0.0f, 0.0f};
  c.up = {0.0f, 0.0f, 1.0f};
  c.verticalFovDeg = 45.0f;
  c.nearMm = 5.0f;
  c.farMm = 5000.0f;
  return c;
}

// A point `rightMm`, `upMm` and `forwardMm` from the bench camera's eye along its axes.
Float3 inView(float rightMm, float upMm, float forwardMm) {
  const render::Camera c = benchCamera();
  const Float3 f = normalize(c.target - c.eye);
  const Float3 r = normalize(cross(f, c.up));
  const Float3 u = cross(r, f);
  return c.eye + rightMm * r + upMm * u + forwardMm * f;
}

// The organs: the poked one first and nearest, the close-up a trainee works on at laparoscope
// distance (its nearest surface about 100 mm from the eye, 1-1.5 px per mm at 128 x 96, so the
// red band's ~1-3 mm diffusion is resolved: where the methods differ), two at mid distance, two
// far and small.
struct Placement {
  const char* name;
  Mat4 model;
};
std::vector<Placement> placements() {
  return {{"poked (close-up)", placed(inView(-40, -30, 165), 0)},
          {"mid 1", placed(inView(75, 25, 420), -20)},
          {"mid 2", placed(inView(-60, 90, 560), 35)},
          {"far 1", placed(inView(-260, 330, 1500), 60)},
          {"far 2", placed(inView(420, 560, 2200), -40)}};
}

// The laparoscope's light: beside the optics (a light port offset from the lens), so that the
// poke's dimple and the organs' curvature shade and cast short shadows.
render::Light benchLight() {
  return detail::lightBesideLens(benchCamera());
}

double percentile(std::vector<double> v, double q) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const std::size_t i = std::size_t(std::ceil(q * double(v.size()))) - 1;
  return v[std::min(i, v.size() - 1)];
}

// The controller's planning costs on the organs' last footprints (BudgetRun::learnedCosts).
void learnedCosts(const quality::QualityController& q, BudgetRun& r) {
  const std::vector<quality::CostModel> costs = q.planningCosts();
  const std::vector<double> pass = q.planningPassMs();
  quality::ControllerSettings uncharged = q.settings();  // the expected error as reported: no charge
  uncharged.errorConfidence = 0.0;
  for (std::size_t o = 0; o < costs.size(); ++o) {
    LearnedOptionCost c;
    c.method = q.table().options[o].method;
    c.setting = q.table().options[o].setting;
    c.samples = q.costs()[o].samples;
    c.passMs = o < pass.size() ? pass[o] : 0.0;
    for (const scene::BudgetChoice& organ : r.choices) {
      c.organMs.push_back(costs[o].predictMs(organ.footprintPx));
      quality::ObjectView view;
      view.footprintPx = organ.footprintPx;
      view.viewAngleDeg = organ.viewAngleDeg;
      const auto cls = quality::viewClassOfFrame(organ.view);
      c.organExpectedRelRms.push_back(
          cls ? std::sqrt(quality::expectedSquaredError(q.table(), int(o), view, *cls, uncharged))
              : std::nan(""));
    }
    r.learnedCosts.push_back(std::move(c));
  }
  r.learnedOverheadMs = q.overheadMs();
}

struct Bench {
  const BudgetBenchConfig& config;
  scene::Scene scene;
  std::vector<std::vector<Float3>> shapes;  // the poked organ's geometric positions per frame
  const truth::TruthImage* truth = nullptr;
  std::vector<Float3> truthLinear;
  std::vector<std::vector<std::uint8_t>> organMasks;  // per organ
  std::vector<std::uint8_t> interiorMask;
  std::vector<Float3> lastImage;  // the last run's linear radiance

  // One run: warm-up and timed frames cycling through the poke, then the last shape scored.
  Result<BudgetRun> run(double abortMs = 1e30) {
    BudgetRun r;
    std::vector<double> ms;
    const int total = config.warmupFrames + config.timedFrames;
    int slow = 0;
    const int changesBefore = scene.qualityController() ? scene.qualityController()->plansChanged() : 0;
    const int deferredBefore = scene.qualityController() ? scene.qualityController()->switchesDeferred() : 0;
    for (int f = 0; f < total; ++f) {
      // Forth and back through the recorded poke, ending on its deepest frame.
      const std::size_t n = shapes.size();
      const std::size_t back = std::size_t(total - 1 - f) % (2 * n - 2);
      const std::size_t k = back < n ? n - 1 - back : back - (n - 1);
      if (auto ok = scene.setPositions(0, shapes[k]); !ok) return ok.error();
      const int plansBefore = scene.qualityController() ? scene.qualityController()->plansChanged() : 0;
      const Stopwatch watch;
      auto image = scene.renderImage(config.width, config.height);
      if (!image) return image.error();
      const double frameMs = watch.elapsedMs();
      if (f == 0) r.firstFrameMs = frameMs;
      const quality::QualityController* q = scene.qualityController();
      const bool changed = q && q->plansChanged() != plansBefore;
      if (f >= config.warmupFrames) {
        if (changed) r.planChangeFrames.push_back(int(ms.size()));
        if (q) {
          r.framePredictedMs.push_back(q->plan().predictedMs);
          r.framePlannedForMs.push_back(q->planningBudgetMs(scene.budgetMs()));
        }
        ms.push_back(frameMs);
      } else if (changed) {
        r.warmupPlanChangeFrames.push_back(f);
      }
      // Five frames in a row over the cap (a shared machine's stalls come one at a time); the
      // first frame warms up (shaders, maps).
      slow = f > 0 && frameMs > abortMs ? slow + 1 : 0;
      if (slow >= 5) {
        r.tooSlow = true;
        r.frameMsMedian = r.frameMsP95 = frameMs;
        r.relRms = r.relRmsDebiased = std::nan("");
        return r;
      }
    }
    r.frameMsMedian = percentile(ms, 0.5);
    r.frameMsP95 = percentile(ms, 0.95);
    r.frameMs = ms;
    auto linear = lastFrameRadiance(scene.renderer());
    if (!linear) return linear.error();
    const AtlasScore score = scoreAgainstTruth(truthLinear, *linear, truth->covered);
    r.relRms = score.relRms;
    r.gain = score.gain;
    r.shapeRelRms = score.shapeRelRms;
    r.relRmsDebiased = debiasedError(score.relRms, truthNoiseRelRms(*truth));
    for (const auto& mask : organMasks) {
      const AtlasScore organ = scoreAgainstTruth(truthLinear, *linear, mask);
      r.organRelRms.push_back(organ.relRms);
      r.organGain.push_back(organ.gain);
      r.organShapeRelRms.push_back(organ.shapeRelRms);
    }
    r.interiorRelRms = scoreAgainstTruth(truthLinear, *linear, interiorMask).relRms;
    lastImage = std::move(*linear);
    r.choices = scene.budgetChoices();
    if (scene.qualityController()) {
      r.planChanges = scene.qualityController()->plansChanged() - changesBefore;
      r.switchesDeferred = scene.qualityController()->switchesDeferred() - deferredBefore;
      r.plannedForMs = scene.qualityController()->planningBudgetMs(scene.budgetMs());
      r.predictedMs = scene.qualityController()->plan().predictedMs;
      learnedCosts(*scene.qualityController(), r);
    }
    return r;
  }
};

// A figure, or null where there is none (NaN: no fixed setting fits the budget).
nlohmann::json orNull(double v) {
  return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json();
}

std::string jsonOf(const BudgetBenchResult& b, const BudgetBenchConfig& config) {
  nlohmann::json results = nlohmann::json::array(), fixedRuns = nlohmann::json::array(),
                 runs = nlohmann::json::array();
  for (const BudgetResult& r : b.results)
    results.push_back({{"budget_ms", r.budgetMs},
                       {"frame_ms_median", r.frameMsMedian},
                       {"frame_ms_p95", r.frameMsP95},
                       {"rel_rms", r.relRms},
                       {"rel_rms_debiased", r.relRmsDebiased},
                       {"fixed_best_rel_rms", orNull(r.fixedBestRelRms)},
                       {"fixed_best_rel_rms_debiased", orNull(r.fixedBestRelRmsDebiased)},
                       {"fixed_best", r.fixedBest},
                       {"fixed_best_within_10_percent", r.fixedBestWithinTenPercent},
                       {"fixed_best_within_10_percent_rel_rms", orNull(r.fixedBestWithinTenPercentRelRms)},
                       {"p95_within_10_percent", r.withinTenPercent},
                       {"squared_difference", orNull(r.squaredDifference)},
                       {"squared_difference_stderr", orNull(r.squaredDifferenceStderr)},
                       {"beats_fixed", r.beatsFixed},
                       {"loses_to_fixed", r.losesToFixed}});
  for (const BudgetRun& f : b.fixed)
    fixedRuns.push_back({{"method", f.method},
                         {"setting", f.setting},
                         {"frame_ms_median", f.frameMsMedian},
                         {"frame_ms_p95", f.frameMsP95},
                         {"first_frame_ms", f.firstFrameMs},
                         {"rel_rms", f.relRms},
                         {"rel_rms_debiased", f.relRmsDebiased},
                         {"rel_rms_off_silhouettes", f.interiorRelRms},
                         {"organ_rel_rms", f.organRelRms},
                         {"organ_gain", f.organGain},
                         {"organ_shape_rel_rms", f.organShapeRelRms},
                         {"too_slow", f.tooSlow}});
  const auto names = placements();
  for (const BudgetRun& c : b.controller) {
    nlohmann::json choices = nlohmann::json::array();
    for (std::size_t i = 0; i < c.choices.size(); ++i) {
      nlohmann::json choice = detail::budgetChoiceJson(c.choices[i]);
      choice["organ"] = i < names.size() ? names[i].name : "";
      choices.push_back(std::move(choice));
    }
    nlohmann::json learned = nlohmann::json::array();
    for (const LearnedOptionCost& l : c.learnedCosts)
      learned.push_back({{"method", l.method},
                         {"setting", l.setting},
                         {"samples", l.samples},
                         {"organ_ms", l.organMs},
                         {"organ_expected_rel_rms", l.organExpectedRelRms},
                         {"pass_ms", l.passMs}});
    runs.push_back({{"budget_ms", c.budgetMs},
                    {"plan_changes", c.planChanges},
                    {"switches_deferred", c.switchesDeferred},
                    {"planned_for_ms", c.plannedForMs},
                    {"predicted_ms", c.predictedMs},
                    {"frame_ms", c.frameMs},
                    {"plan_change_frames", c.planChangeFrames},
                    {"warmup_plan_change_frames", c.warmupPlanChangeFrames},
                    {"frame_predicted_ms", c.framePredictedMs},
                    {"frame_planned_for_ms", c.framePlannedForMs},
                    {"rel_rms_off_silhouettes", c.interiorRelRms},
                    {"organ_rel_rms", c.organRelRms},
                    {"organ_gain", c.organGain},
                    {"organ_shape_rel_rms", c.organShapeRelRms},
                    {"choices", choices},
                    {"learned_overhead_ms", c.learnedOverheadMs},
                    {"learned_costs", learned}});
  }
  const nlohmann::json json = {{"width", config.width},
                               {"height", config.height},
                               {"session_frames", {config.firstFrame, config.lastFrame}},
                               {"timed_frames", config.timedFrames},
                               {"warmup_frames", config.warmupFrames},
                               {"artist_terms", config.artistTerms},
                               {"truth",
                                {{"samples_per_pixel", b.truthSpp},
                                 {"ms", b.truthMs},
                                 {"noise_rel_rms", b.truthNoiseRelRms},
                                 {"organ_pixels", b.organPixels},
                                 {"organ_pixels_off_silhouettes", b.interiorPixels}}},
                               {"organs", b.organNames},
                               {"organ_pixel_counts", b.organPixelCounts},
                               {"results", results},
                               {"fixed", fixedRuns},
                               {"controller", runs}};
  return detail::jsonText(json);
}

void writeReport(BudgetBenchResult& b, const BudgetBenchConfig& config) {
  b.output.json = jsonOf(b, config);
  Report& report = b.output.report;
  report.add("budget_bench.json", b.output.json);
  Table t{{"budget ms", "median ms", "p95 ms", "p95 <= 1.1 budget", "rel RMS", "debiased",
           "best fixed that fits", "its rel RMS", "its debiased", "E^2 - E_fixed^2 (+- 1 s.e.)",
           "lower error", "best fixed with p95 <= 1.1 budget", "its rel RMS"},
          {}};
  for (const BudgetResult& r : b.results)
    t.rows.push_back(
        {fixed(r.budgetMs, 1), fixed(r.frameMsMedian, 1), fixed(r.frameMsP95, 1),
         r.withinTenPercent ? "yes" : "no", fixed(r.relRms), fixed(r.relRmsDebiased),
         r.fixedBest.empty() ? "none" : r.fixedBest, fixed(r.fixedBestRelRms),
         fixed(r.fixedBestRelRmsDebiased),
         std::isfinite(r.squaredDifference)
             ? fixed(r.squaredDifference, 5) + " +- " + fixed(r.squaredDifferenceStderr, 5)
             : "-",
         r.beatsFixed ? "yes" : (r.losesToFixed ? "no (higher)" : "no (a tie within the truth's noise)"),
         r.fixedBestWithinTenPercent.empty() ? "none" : r.fixedBestWithinTenPercent,
         fixed(r.fixedBestWithinTenPercentRelRms)});
  Table f{{"fixed setting (all organs)", "median ms", "p95 ms", "rel RMS", "debiased", "off silhouettes"},
          {}};
  for (const std::string& n : b.organNames)
    f.header.push_back(n);
  const auto organCells = [](const BudgetRun& r, std::vector<std::string> row) {
    row.push_back(fixed(r.interiorRelRms));
    for (double e : r.organRelRms)
      row.push_back(fixed(e));
    return row;
  };
  for (const BudgetRun& r : b.fixed)
    if (!r.tooSlow)
      f.rows.push_back(organCells(r, {r.method + " " + r.setting, fixed(r.frameMsMedian, 1),
                                      fixed(r.frameMsP95, 1), fixed(r.relRms), fixed(r.relRmsDebiased)}));
  for (const BudgetRun& r : b.controller)
    f.rows.push_back(organCells(r, {"controller, budget " + fixed(r.budgetMs, 1), fixed(r.frameMsMedian, 1),
                                    fixed(r.frameMsP95, 1), fixed(r.relRms), fixed(r.relRmsDebiased)}));
  Table c{{"budget ms", "organ", "footprint px", "view", "chosen", "predicted ms"}, {}};
  const auto names = placements();
  for (const BudgetRun& r : b.controller)
    for (std::size_t i = 0; i < r.choices.size(); ++i)
      c.rows.push_back(
          {fixed(r.budgetMs, 1), i < names.size() ? names[i].name : "", fixed(r.choices[i].footprintPx, 0),
           r.choices[i].view,
           r.choices[i].method + " " + r.choices[i].setting + (r.choices[i].fallback ? " (fallback)" : ""),
           fixed(r.choices[i].predictedMs, 2)});
  char truthLine[256];
  std::snprintf(
      truthLine, sizeof truthLine,
      "Truth: %d spp, %.0f s, %d organ pixels (%d off the silhouettes), noise rel RMS %.3f (debiased = "
      "sqrt(err^2 - noise^2)).\n\n",
      b.truthSpp, b.truthMs / 1e3, b.organPixels, b.interiorPixels, b.truthNoiseRelRms);
  b.output.summary = markdownTable(t);
  report.add("budget_bench.md", "# Budget bench\n\n" + std::string(truthLine) + markdownTable(t) + "\n" +
                                    markdownTable(f) + "\n" + markdownTable(c));
  ReportChart chart;
  chart.name = "budget_bench.png";
  chart.settings.title = "error against frame budget: controller vs best fixed setting that fits";
  chart.settings.xLabel = "frame budget (ms)";
  chart.settings.yLabel = "rel RMS against the truth (debiased)";
  inspect::ChartSeries ctl{"controller", {}, {}, true}, best{"best fixed setting that fits", {}, {}, true};
  for (const BudgetResult& r : b.results) {
    ctl.x.push_back(r.budgetMs);
    ctl.y.push_back(r.relRmsDebiased);
    if (std::isfinite(r.fixedBestRelRmsDebiased)) {
      best.x.push_back(r.budgetMs);
      best.y.push_back(r.fixedBestRelRmsDebiased);
    }
  }
  chart.series = {ctl, best};
  report.charts.push_back(std::move(chart));
}

}  // namespace

Result<BudgetBenchResult> runBudgetBench(const BudgetBenchConfig& config) {
  const auto say = [&](const std::string& line) {
    if (config.onProgress) config.onProgress(line);
  };
  if (config.lastFrame <= config.firstFrame || config.firstFrame < 0)
    return Error{"budget bench: give session frames first < last"};
  // Checked before the replay and the truth: a bad budget would fail only after minutes of runs.
  for (double b : config.budgetsMs)
    if (!(b > 0.0) || !std::isfinite(b))
      return Error{"budget bench: budget " + std::to_string(b) + " ms: give frame budgets in ms > 0"};
  if (config.width < 1 || config.height < 1)
    return Error{"budget bench: the image must be at least 1 x 1 pixels"};
  if (config.timedFrames < 1 || config.warmupFrames < 0)
    return Error{"budget bench: give at least 1 timed frame and 0 or more warm-up frames per run"};
  // 1 the session's poke as shapes: its scenario's loop, stepped without GL.
  auto session = scene::loadSession(config.session);
  if (!session) return session.error();
  scene::OrganDesc poked{.mesh = config.mesh, .material = config.material, .scenario = session->scenario};
  auto simulated = scene::loadSimulatedOrgan(poked, config.scene);
  if (!simulated) return simulated.error();
  scene::OrganLoopConfig loopConfig;
  loopConfig.planes = simulated->assets.planes;
  auto loop = scene::OrganLoop::create(simulated->scenario, simulated->assets.mesh, loopConfig);
  if (!loop) return loop.error();
  if (auto ok = scene::checkSessionMatches(*session, *loop); !ok) return ok.error();
  if (std::size_t(config.lastFrame) >= session->frames.size())
    return Error{config.session.string() + ": has " + std::to_string(session->frames.size()) +
                 " frames; ask for fewer"};
  say("replaying " + config.session.filename().string() + " to frame " + std::to_string(config.lastFrame));
  std::vector<std::vector<Float3>> shapes;
  for (int f = 0; f <= config.lastFrame; ++f) {
    auto step = loop->step(scene::sessionInput(*session, std::size_t(f)));
    if (!step) return step.error();
    if (f >= config.firstFrame) {
      const auto g = loop->geometricPositions();
      shapes.emplace_back(g.begin(), g.end());
    }
  }
  // 2 the scene: the organs as static meshes, the poked one's shape set per frame.
  scene::SceneSettings settings = config.scene;
  settings.renderer.finishPasses = true;  // llvmpipe: pass times to completion, for the controller
  settings.renderer.samples = 0;
  if (!config.artistTerms) {  // the truth is lit by the scene's lights alone, off the mesh's shape
    settings.ambient = {};
    settings.normalMaps = false;
  }
  auto created = scene::Scene::create({}, settings);
  if (!created) return created.error();
  Bench bench{config, std::move(*created), std::move(shapes), nullptr, {}, {}, {}, {}};
  scene::Scene& sc = bench.scene;
  for (const Placement& p : placements()) {
    scene::OrganDesc d{.mesh = config.mesh, .material = config.material, .model = p.model};
    auto id = sc.addOrgan(d);
    if (!id) return id.error();
  }
  sc.setCamera(benchCamera());
  sc.renderScene().lights = {benchLight()};  // the bench's own light: it no longer follows the framing
  if (auto first = sc.renderImage(config.width, config.height); !first) return first.error();
  render::Scene frame = sc.renderScene();  // the lights as framed; they stay
  frame.camera = sc.camera();
  // 3 the truth of the last frame: the organs' transformed meshes as one, their one material.
  scene::OrganAssets all = sc.assets(0);
  all.mesh = SurfaceMesh{};
  std::vector<Float3> world;
  std::vector<std::uint32_t> firstTriangle;
  const auto places = placements();
  for (std::size_t i = 0; i < places.size(); ++i) {
    const scene::OrganAssets& a = sc.assets(i);
    const auto base = std::uint32_t(world.size());
    firstTriangle.push_back(std::uint32_t(all.mesh.triangles.size()));
    for (std::size_t v = 0; v < a.mesh.positions.size(); ++v) {
      const Float3 p = i == 0 ? bench.shapes.back()[a.mesh.geometricIndex[v]] : a.mesh.positions[v];
      world.push_back(transformPoint(places[i].model, p));
      all.mesh.positions.push_back(world.back());
      all.mesh.uvs.push_back(a.mesh.uvs[v]);
    }
    for (const Triangle& t : a.mesh.triangles)
      all.mesh.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
  }
  truth::PathTraceSettings ts;
  ts.width = config.width;
  ts.height = config.height;
  ts.samplesPerPass = 4;
  ts.passes = std::max(1, config.truthSpp / ts.samplesPerPass);
  ts.threads = config.threads;
  ts.seed = 16;
  ts.onPass = [&](const truth::PathTraceProgress& p) {
    char line[128];
    std::snprintf(line, sizeof line, "truth: %d spp, %.0f s, mean relative stderr %.3f", p.samplesPerPixel,
                  p.seconds, p.meanRelativeStderr);
    say(line);
    return p.seconds < config.truthSeconds;
  };
  // The atlas's cache: its key, its file format (written atomically).
  std::filesystem::path cacheFile;
  std::optional<truth::TruthImage> cached;
  if (!config.truthCacheDir.empty()) {
    auto material = scene::truthMaterialOf(all);
    if (!material) return material.error();
    const std::uint64_t key = detail::truthKey(world, all.mesh, *material, frame, ts, config.truthSeconds);
    cacheFile = config.truthCacheDir / detail::truthCacheName("budget", key);
    cached = detail::readTruthCache(cacheFile);
  }
  Result<truth::TruthImage> truthImage =
      cached ? Result<truth::TruthImage>(std::move(*cached)) : scene::renderTruth(all, world, frame, ts);
  if (!truthImage) return truthImage.error();
  if (cached) say("truth from " + cacheFile.string());
  if (!cached && !cacheFile.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(config.truthCacheDir, ec);
    if (auto w = detail::writeTruthCache(cacheFile, *truthImage); !w) return w.error();
  }
  BudgetBenchResult out;
  out.truthSpp = truthImage->samplesPerPixel;
  out.truthMs = 1e3 * truthImage->seconds;
  out.truthNoiseRelRms = truthNoiseRelRms(*truthImage);
  for (std::uint8_t c : truthImage->covered)
    out.organPixels += c;
  bench.truth = &*truthImage;
  bench.truthLinear.assign(truthImage->radiance.begin(), truthImage->radiance.end());
  // Which organ each pixel shows, and which pixels are off every silhouette.
  auto pixels = detail::organPixels(world, all.mesh.triangles, firstTriangle, frame.camera, config.width,
                                    config.height);
  if (!pixels) return pixels.error();
  for (std::size_t i = 0; i < places.size(); ++i) {
    bench.organMasks.push_back(detail::organMask(*pixels, int(i), false));
    out.organNames.push_back(places[i].name);
    int n = 0;
    for (std::uint8_t m : bench.organMasks.back())
      n += m;
    out.organPixelCounts.push_back(n);
  }
  bench.interiorMask = detail::organMask(*pixels, -1, true);
  for (std::uint8_t m : bench.interiorMask)
    out.interiorPixels += m;
  say("organ pixels per organ: " +
      [&] {
        std::string t;
        for (std::size_t i = 0; i < places.size(); ++i)
          t += std::string(i ? ", " : "") + places[i].name + " " + std::to_string(out.organPixelCounts[i]);
        return t;
      }() +
      "; off the silhouettes " + std::to_string(out.interiorPixels) + " of " +
      std::to_string(out.organPixels));
  out.output.report.images.push_back(
      {"truth.png", toneMapped(bench.truthLinear, config.width, config.height)});
  // 4 every table setting on every organ.
  auto loadedTable = quality::qualityTableOrDefault(settings.qualityTable);
  if (!loadedTable) return Error{"budget bench: " + loadedTable.error().message};
  const quality::QualityTable table = std::move(*loadedTable);
  std::map<std::string, std::tuple<double, Image8, Image8>> bestOfMethod;  // rel RMS, frame, error
  std::vector<std::vector<Float3>> fixedImages;  // each fixed run's last frame, linear
  for (const quality::QualityOption& option : table.options) {
    for (std::size_t i = 0; i < sc.organCount(); ++i)
      if (auto ok = sc.setMethodOption(i, option); !ok) return ok.error();
    auto r = bench.run(config.maxFixedFrameMs);
    if (!r) return Error{"budget bench: " + option.method + " " + option.setting + ": " + r.error().message};
    r->method = option.method;
    r->setting = option.setting;
    say("fixed " + option.method + " " + option.setting + ": median " + fixed(r->frameMsMedian, 1) +
        " ms, p95 " + fixed(r->frameMsP95, 1) + " ms, rel RMS " + fixed(r->relRms) +
        ", off the silhouettes " + fixed(r->interiorRelRms) + ", gain " + fixed(r->gain) + ", shape " +
        fixed(r->shapeRelRms) + ", first frame " + fixed(r->firstFrameMs, 1) + " ms");
    // Each method's best setting: its frame and error image.
    if (!r->tooSlow) {
      auto& [bestRelRms, frameImage, error] = bestOfMethod[option.method];
      if (frameImage.pixels.empty() || r->relRms < bestRelRms) {
        bestRelRms = r->relRms;
        frameImage = toneMapped(bench.lastImage, config.width, config.height);
        error =
            errorImage(bench.truthLinear, bench.lastImage, truthImage->covered, config.width, config.height);
      }
    }
    out.fixed.push_back(std::move(*r));
    fixedImages.push_back(bench.lastImage);
  }
  for (auto& [method, best] : bestOfMethod) {
    out.output.report.images.push_back({"frame_fixed_" + method + ".png", std::move(std::get<1>(best))});
    out.output.report.images.push_back({"error_fixed_" + method + ".png", std::move(std::get<2>(best))});
  }
  // 5 the budgets: given, or from the fixed settings' p95 times (tight: 1.15 x the cheap end, the
  // 25th percentile: the least of 30 noisy p95s is one setting's lucky 40 frames, and a budget
  // only it fits leaves the controller no choice; loose: the dearest but the slowest outliers;
  // one between; docs/DECISIONS.md, "The tight budget is set by the cheap settings, not the
  // luckiest").
  std::vector<double> budgets = config.budgetsMs;
  if (budgets.empty()) {
    std::vector<double> p95;
    for (const BudgetRun& f : out.fixed)
      p95.push_back(f.frameMsP95);
    std::sort(p95.begin(), p95.end());
    const double tight = 1.15 * p95[std::size_t(0.25 * double(p95.size() - 1))];
    const double loose = std::max(2.0 * tight, p95[std::size_t(0.75 * double(p95.size() - 1))]);
    budgets = {tight, std::sqrt(tight * loose), loose};
  }
  // 6 the controller under each budget.
  for (double budget : budgets) {
    if (auto ok = sc.setBudgetMs(budget); !ok) return ok.error();
    // The options' settings built before the timed frames, as a host's loading screen does
    // (Scene::prepareBudgetOptions) and as each fixed setting's were (setMethodOption): the bench
    // measures the controller's choice among all options, not how soon an idle-priority worker
    // gets a core. After the fixed runs none is pending (the scene keeps the settings they built);
    // a table with options the fixed runs lack would wait here.
    const std::size_t pending = sc.budgetOptionsPending();
    const Stopwatch prepare;
    if (auto ok = sc.prepareBudgetOptions(); !ok) return ok.error();
    if (pending > 0)
      say("budget " + fixed(budget, 1) + " ms: " + std::to_string(pending) +
          " option settings built first (" + fixed(prepare.elapsedMs(), 0) + " ms)");
    auto r = bench.run();
    if (!r) return Error{"budget bench: budget " + fixed(budget, 1) + " ms: " + r.error().message};
    r->budgetMs = budget;
    say("budget " + fixed(budget, 1) + " ms: median " + fixed(r->frameMsMedian, 1) + " ms, p95 " +
        fixed(r->frameMsP95, 1) + " ms, rel RMS " + fixed(r->relRms));
    const std::string tag = "budget_" + fixed(budget, 0);
    out.output.report.images.push_back(
        {"frame_" + tag + ".png", toneMapped(bench.lastImage, config.width, config.height)});
    out.output.report.images.push_back(
        {"error_" + tag + ".png",
         errorImage(bench.truthLinear, bench.lastImage, truthImage->covered, config.width, config.height)});
    BudgetResult res;
    res.budgetMs = budget;
    res.frameMsMedian = r->frameMsMedian;
    res.frameMsP95 = r->frameMsP95;
    res.relRms = r->relRms;
    res.relRmsDebiased = r->relRmsDebiased;
    res.fixedBestRelRms = res.fixedBestRelRmsDebiased = res.fixedBestWithinTenPercentRelRms = std::nan("");
    std::size_t best = out.fixed.size();
    for (std::size_t k = 0; k < out.fixed.size(); ++k) {
      const BudgetRun& f = out.fixed[k];
      if (f.tooSlow) continue;
      if (f.frameMsP95 <= budget && !(f.relRms >= res.fixedBestRelRms)) {
        res.fixedBestRelRms = f.relRms;
        res.fixedBestRelRmsDebiased = f.relRmsDebiased;
        res.fixedBest = f.method + " " + f.setting;
        best = k;
      }
      if (f.frameMsP95 <= 1.1 * budget && !(f.relRms >= res.fixedBestWithinTenPercentRelRms)) {
        res.fixedBestWithinTenPercentRelRms = f.relRms;
        res.fixedBestWithinTenPercent = f.method + " " + f.setting;
      }
    }
    res.withinTenPercent = res.frameMsP95 <= 1.1 * budget;
    // Lower only where the truth can tell: the two errors differ by far less than the truth's
    // noise, so a difference in the fourth decimal is a tie, not a win.
    res.squaredDifference = res.squaredDifferenceStderr = std::nan("");
    res.beatsFixed = best == out.fixed.size();
    res.losesToFixed = false;
    if (best < out.fixed.size()) {
      const ErrorDifference d = errorDifference(bench.truthLinear, truthImage->stderrs, bench.lastImage,
                                                fixedImages[best], truthImage->covered);
      res.squaredDifference = d.squared;
      res.squaredDifferenceStderr = d.squaredStderr;
      res.beatsFixed = d.aLower();
      res.losesToFixed = d.bLower();
    }
    out.results.push_back(res);
    out.controller.push_back(std::move(*r));
  }
  (void)sc.setBudgetMs(0.0);
  writeReport(out, config);
  return out;
}

}  // namespace tissue::studies
