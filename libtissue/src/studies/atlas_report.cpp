// The atlas's truth cache and its report (atlas_detail.h).
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <map>
#include <set>

#include "atlas_detail.h"
#include "json_text.h"

namespace tissue::studies::detail {
namespace {

constexpr std::uint32_t kCacheMagic = 0x41544c31;  // "ATL1"

struct Hasher {
  std::uint64_t h = 0xcbf29ce484222325ull;
  void bytes(const void* p, std::size_t n) {
    const auto* b = static_cast<const unsigned char*>(p);
    for (std::size_t i = 0; i < n; ++i)
      h = (h ^ b[i]) * 0x100000001b3ull;
  }
  template <class T>
  void value(const T& v) {
    bytes(&v, sizeof v);
  }
  template <class T>
  void span(std::span<const T> v) {
    bytes(v.data(), v.size_bytes());
  }
};

const char* const kMethods[] = {"lit", "separable", "texture-space", "ray-march", "parallax"};

}  // namespace

std::uint64_t truthKey(std::span<const Float3> positions, const SurfaceMesh& mesh,
                       const truth::TruthMaterial& material, const render::Scene& frame,
                       const truth::PathTraceSettings& s, double budgetS) {
  Hasher h;
  h.span(positions);
  h.span(std::span<const Triangle>(mesh.triangles));
  h.span(std::span<const Float2>(mesh.uvs));
  for (const truth::TruthLayer& l : material.layers) {
    h.value(*l.sigmaA);
    h.value(*l.sigmaS);
    h.value(l.g);
    h.value(l.n);
    h.value(l.thicknessMm);
  }
  h.value(material.ambientN);
  h.value(material.depthScaleMm);
  h.value(material.maps.width);
  h.value(material.maps.height);
  h.value(material.maps.mapCount);
  h.span(std::span<const float>(material.maps.depths));
  h.value(frame.camera.eye);
  h.value(frame.camera.target);
  h.value(frame.camera.up);
  h.value(frame.camera.verticalFovDeg);
  for (const render::Light& l : frame.lights) {
    h.value(l.type);
    h.value(l.positionMm);
    h.value(l.direction);
    h.value(l.color);
    h.value(l.intensity);
  }
  h.value(frame.material.shininess);
  for (int v : {s.width, s.height, s.samplesPerPass, s.passes, s.maxInteractions})
    h.value(v);
  h.value(s.seed);
  h.value(s.rouletteWeight);
  h.value(budgetS);
  return h.h;
}

std::string truthCacheName(const std::string& frame, std::uint64_t key) {
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016" PRIx64, key);
  // The tracer's version: raise it when the estimator changes, so that old images are not reused.
  // v2: local majorants; v3: the next-event MIS towards the beams (new estimators, new noise);
  // v4: the glossy reflection off the interpolated (smooth) normal.
  return "truth_v4_" + frame + "_" + hex + ".bin";
}

std::optional<truth::TruthImage> readTruthCache(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return std::nullopt;
  std::uint32_t magic = 0;
  truth::TruthImage img;
  in.read(reinterpret_cast<char*>(&magic), sizeof magic);
  in.read(reinterpret_cast<char*>(&img.width), sizeof img.width);
  in.read(reinterpret_cast<char*>(&img.height), sizeof img.height);
  in.read(reinterpret_cast<char*>(&img.samplesPerPixel), sizeof img.samplesPerPixel);
  in.read(reinterpret_cast<char*>(&img.seconds), sizeof img.seconds);
  if (!in || magic != kCacheMagic || img.width < 1 || img.height < 1 || img.width > 16384 ||
      img.height > 16384)
    return std::nullopt;
  const std::size_t n = std::size_t(img.width) * std::size_t(img.height);
  img.radiance.resize(n);
  img.stderrs.resize(n);
  img.covered.resize(n);
  in.read(reinterpret_cast<char*>(img.radiance.data()), std::streamsize(n * sizeof(Float3)));
  in.read(reinterpret_cast<char*>(img.stderrs.data()), std::streamsize(n * sizeof(Float3)));
  in.read(reinterpret_cast<char*>(img.covered.data()), std::streamsize(n));
  if (!in) return std::nullopt;
  return img;
}

Result<void> writeTruthCache(const std::filesystem::path& file, const truth::TruthImage& img) {
  std::error_code ec;
  std::filesystem::create_directories(file.parent_path(), ec);
  const std::filesystem::path tmp = file.string() + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary);
    const std::uint32_t magic = kCacheMagic;
    out.write(reinterpret_cast<const char*>(&magic), sizeof magic);
    out.write(reinterpret_cast<const char*>(&img.width), sizeof img.width);
    out.write(reinterpret_cast<const char*>(&img.height), sizeof img.height);
    out.write(reinterpret_cast<const char*>(&img.samplesPerPixel), sizeof img.samplesPerPixel);
    out.write(reinterpret_cast<const char*>(&img.seconds), sizeof img.seconds);
    out.write(reinterpret_cast<const char*>(img.radiance.data()),
              std::streamsize(img.radiance.size() * sizeof(Float3)));
    out.write(reinterpret_cast<const char*>(img.stderrs.data()),
              std::streamsize(img.stderrs.size() * sizeof(Float3)));
    out.write(reinterpret_cast<const char*>(img.covered.data()), std::streamsize(img.covered.size()));
    if (!out) return Error{"atlas: cannot write the truth cache " + tmp.string() + "; check the folder"};
  }
  std::filesystem::rename(tmp, file, ec);
  if (ec) return Error{"atlas: cannot rename " + tmp.string() + " to " + file.string() + ": " + ec.message()};
  return {};
}

void writeAtlasReport(AtlasResult& result, const AtlasConfig& config,
                      const std::vector<std::pair<std::string, std::string>>& skipped) {
  // The truth's summary: the fewest samples, the whole time, the largest noise.
  int minSpp = 1 << 30;
  double truthMs = 0.0, maxNoise = 0.0;
  std::map<std::string, double> noiseOf;
  for (const AtlasTruth& t : result.truths) {
    minSpp = std::min(minSpp, t.samplesPerPixel);
    truthMs += t.cachedMs;  // the time the images took, traced now or before
    maxNoise = std::max(maxNoise, t.noiseRelRms);
    noiseOf[t.frame] = t.noiseRelRms;
  }
  double bestErr = 1e30;
  std::map<std::string, double> bestOf;  // per frame: the smallest rel RMS of any method
  for (const AtlasRow& r : result.rows)
    if (std::isfinite(r.relRms)) {
      bestErr = std::min(bestErr, r.relRms);
      auto it = bestOf.find(r.frame);
      if (it == bestOf.end() || r.relRms < it->second) bestOf[r.frame] = r.relRms;
    }
  int meeting = 0;
  for (const AtlasTruth& t : result.truths)
    meeting += t.noiseRelRms < bestOf[t.frame] / 3.0 ? 1 : 0;
  nlohmann::json truthJson = {{"samples_per_pixel", minSpp},
                              {"ms", truthMs},
                              {"noise_rel_rms", maxNoise},
                              {"best_method_rel_rms", bestErr},
                              {"noise_over_best", bestErr > 0.0 ? maxNoise / bestErr : 0.0},
                              {"frames_with_noise_below_a_third_of_best", meeting},
                              {"frames", nlohmann::json::array()}};
  for (const AtlasTruth& t : result.truths)
    truthJson["frames"].push_back(
        {{"frame", t.frame},
         {"samples_per_pixel", t.samplesPerPixel},
         {"ms", t.fromCache ? t.cachedMs : t.ms},
         {"from_cache", t.fromCache},
         {"noise_rel_rms", t.noiseRelRms},
         {"best_method_rel_rms", bestOf[t.frame]},
         {"noise_over_best", bestOf[t.frame] > 0.0 ? t.noiseRelRms / bestOf[t.frame] : 0.0},
         {"noise_below_a_third_of_best", t.noiseRelRms < bestOf[t.frame] / 3.0},
         {"organ_pixels", t.organPixels},
         {"view_angle_deg", t.viewAngleDeg}});
  nlohmann::json rows = nlohmann::json::array();
  for (const AtlasRow& r : result.rows)
    rows.push_back({{"method", r.method},
                    {"setting", r.setting},
                    {"frame", r.frame},
                    {"ms", r.ms},
                    {"rel_rms", r.relRms},
                    {"rel_rms_debiased", debiasedError(r.relRms, noiseOf[r.frame])},
                    {"psnr_db", r.psnrDb},
                    {"gain", r.gain},
                    {"shape_rel_rms", r.shapeRelRms},
                    {"squared_vs_best", r.squaredVsBest},
                    {"squared_vs_best_stderr", r.squaredVsBestStderr},
                    {"worse_than_best", r.worseThanBest}});
  nlohmann::json skips = nlohmann::json::array();
  for (const auto& [what, why] : skipped)
    skips.push_back({{"setting", what}, {"reason", why}});
  const nlohmann::json json = {{"width", config.width},
                               {"height", config.height},
                               {"quick", config.quick},
                               {"artist_terms", config.artistTerms},
                               {"gl_renderer", config.glRenderer},
                               {"truth", truthJson},
                               {"results", rows},
                               {"skipped", skips}};
  result.output.json = jsonText(json);
  Report& report = result.output.report;
  report.add("atlas.json", result.output.json);

  // Per frame and method: the best setting, and whether it is on the frame's Pareto front.
  Table best{
      {"frame", "method", "best setting", "ms", "rel RMS", "debiased", "PSNR dB", "gain", "shape rel RMS",
       "on front", "truth noise", "E^2 - E_best^2 (+- 1 s.e.)", "vs the frame's best"},
      {}};
  Table truths{
      {"frame", "spp", "truth s", "organ pixels", "noise rel RMS", "best method rel RMS", "noise / best"},
      {}};
  Table all{{"method", "setting", "frame", "ms", "rel_rms", "psnr_db", "gain", "shape_rel_rms"}, {}};
  std::set<std::string> frames;
  for (const AtlasRow& r : result.rows) {
    frames.insert(r.frame);
    all.rows.push_back({r.method, r.setting, r.frame, fixed(r.ms, 2), general(r.relRms, 4),
                        fixed(r.psnrDb, 2), general(r.gain, 3), general(r.shapeRelRms, 3)});
  }
  for (const AtlasTruth& t : result.truths) {
    std::vector<const AtlasRow*> rs;
    std::vector<double> cost, err;
    for (const AtlasRow& r : result.rows)
      if (r.frame == t.frame) rs.push_back(&r), cost.push_back(r.ms), err.push_back(r.relRms);
    const std::vector<std::size_t> front = paretoFront(cost, err);
    std::set<const AtlasRow*> onFront;
    for (std::size_t i : front)
      onFront.insert(rs[i]);
    for (const char* m : kMethods) {
      const AtlasRow* b = nullptr;
      for (const AtlasRow* r : rs)
        if (r->method == m && (!b || r->relRms < b->relRms)) b = r;
      if (!b) continue;
      bool methodOnFront = false;
      for (const AtlasRow* r : onFront)
        methodOnFront |= r->method == m;
      best.rows.push_back(
          {t.frame, m, b->setting, fixed(b->ms, 2), general(b->relRms, 3),
           general(debiasedError(b->relRms, t.noiseRelRms), 3), fixed(b->psnrDb, 2), general(b->gain, 3),
           general(b->shapeRelRms, 3), methodOnFront ? "yes" : "no", general(t.noiseRelRms, 3),
           general(b->squaredVsBest, 3) + " +- " + general(b->squaredVsBestStderr, 2),
           b->squaredVsBest == 0.0 ? "best" : (b->worseThanBest ? "worse" : "tie (within the noise)")});
    }
    truths.rows.push_back({t.frame, std::to_string(t.samplesPerPixel), fixed(1e-3 * t.cachedMs, 1),
                           std::to_string(t.organPixels), general(t.noiseRelRms, 3),
                           general(bestOf[t.frame], 3),
                           general(bestOf[t.frame] > 0.0 ? t.noiseRelRms / bestOf[t.frame] : 0.0, 3)});
    // The chart of the frame: ms against rel RMS, log-log, a colour per method, the front drawn.
    ReportChart chart;
    chart.name = t.frame == "poked" ? "atlas.png" : "atlas_" + t.frame + ".png";
    chart.settings.title = "Speed against error vs the path-traced truth (" + t.frame + ", " +
                           std::to_string(config.width) + "x" + std::to_string(config.height) + ")";
    chart.settings.xLabel = "frame time (ms, llvmpipe)";
    chart.settings.yLabel = "relative RMS of linear radiance";
    chart.settings.logX = chart.settings.logY = true;
    for (const char* m : kMethods) {
      inspect::ChartSeries s{m, {}, {}, false};
      for (const AtlasRow* r : rs)
        if (r->method == m && r->ms > 0.0 && r->relRms > 0.0) s.x.push_back(r->ms), s.y.push_back(r->relRms);
      if (!s.x.empty()) chart.series.push_back(s);
    }
    inspect::ChartSeries f{"Pareto front", {}, {}, true};
    for (std::size_t i : front)
      if (cost[i] > 0.0 && err[i] > 0.0) f.x.push_back(cost[i]), f.y.push_back(err[i]);
    if (!f.x.empty()) chart.series.push_back(f);
    if (t.noiseRelRms > 0.0 && !f.x.empty())
      chart.series.push_back(
          {"truth noise", {f.x.front(), f.x.back() * 1.01}, {t.noiseRelRms, t.noiseRelRms}, true});
    if (!chart.series.empty()) report.charts.push_back(std::move(chart));
  }
  // Where the truth's noise is not well below the errors it ranks, say so before any figure.
  const int noisy = int(result.truths.size()) - meeting;
  const std::string noiseNote =
      noisy == 0
          ? std::string{}
          : "**The truth's noise dominates on " + std::to_string(noisy) + " of " +
                std::to_string(result.truths.size()) +
                " frames** (noise over a third of the best error): their raw errors are largely the "
                "truth's noise; compare the debiased column, and trace longer truths (--truth-seconds, "
                "--spp, fewer pixels) to rank the methods.\n\n";
  std::string md = "# Speed-accuracy atlas against the path-traced truth\n\n";
  md += std::to_string(config.width) + " x " + std::to_string(config.height) + " pixels" +
        (config.quick ? " (quick)" : "") + ", GL " + config.glRenderer +
        ". Truth: " + std::to_string(minSpp) + "+ samples per pixel, noise (rel RMS) at most " +
        general(maxNoise, 3) + "; best method rel RMS " + general(bestErr, 3) +
        " (noise / best = " + general(bestErr > 0.0 ? maxNoise / bestErr : 0.0, 3) + "); " +
        std::to_string(meeting) + " of " + std::to_string(result.truths.size()) +
        " frames have the truth's noise below a third of their best method's error.\n\n" + noiseNote +
        "![atlas](atlas.png)\n\n## The truth per frame\n\n" + markdownTable(truths) +
        "\n## Best setting per frame and method (debiased: sqrt(max(0, err^2 - noise^2)))\n\n"
        "The last two columns compare each method's best setting with the frame's best row on the same "
        "truth: the difference of their squared errors, whose standard error comes from the truth's "
        "per-pixel noise and the two images' difference alone (the noise's own square cancels), so it "
        "resolves differences far below the noise; \"worse\" is more than two standard errors.\n\n" +
        markdownTable(best) + "\n## Every row\n\n" + markdownTable(all);
  if (!skipped.empty()) {
    md += "\n## Skipped\n\n";
    for (const auto& [what, why] : skipped)
      md += "- " + what + ": " + why + "\n";
  }
  report.add("atlas.md", md);
  report.add("atlas.csv", csvTable(all));
  result.output.summary = noiseNote + markdownTable(best);
}

}  // namespace tissue::studies::detail
