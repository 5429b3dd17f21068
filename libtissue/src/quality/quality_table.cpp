// The quality controller's table from the speed-accuracy atlas's JSON (quality_table.h).
#include "tissue/quality/quality_table.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>

namespace tissue::quality {
namespace detail {
const char* embeddedDefaultAtlas();  // default_atlas_embed.cpp, generated from data/quality/
}  // namespace detail
namespace {

// Least squares ms = a + b px over the samples; b clamped at 0 (then a is the mean).
std::pair<double, double> fitLine(const std::vector<std::pair<double, double>>& pxMs) {
  const double n = double(pxMs.size());
  if (pxMs.empty()) return {0.0, 0.0};
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (const auto& [x, y] : pxMs) {
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
  }
  const double det = n * sxx - sx * sx;
  if (det <= 1e-9 * n * sxx) return {sy / n, 0.0};
  const double b = (n * sxy - sx * sy) / det;
  if (b < 0.0) return {sy / n, 0.0};
  return {(sy - b * sx) / n, b};
}

}  // namespace

std::string_view viewClassFrame(ViewClass view) {
  switch (view) {
    case ViewClass::Rest:
      return "rest";
    case ViewClass::Deforming:
      return "poked";
    case ViewClass::CloseUp:
      return "close-up";
    case ViewClass::Grazing:
      return "grazing";
    case ViewClass::Oblique:
      return "oblique";
    case ViewClass::Low:
      return "low";
  }
  return "rest";
}

std::optional<ViewClass> viewClassOfFrame(std::string_view frame) {
  for (std::size_t v = 0; v < kViewClassCount; ++v)
    if (frame == viewClassFrame(ViewClass(v))) return ViewClass(v);
  return std::nullopt;
}

std::string costClassKey(std::string_view method, std::string_view setting) {
  if (method == "lit") return "lit";
  if (method == "separable")
    if (const std::size_t dash = setting.rfind('-'); dash != std::string_view::npos)
      return "separable-" + std::string(setting.substr(dash + 1));
  return std::string(method) + " " + std::string(setting);
}

int QualityTable::find(std::string_view method, std::string_view setting) const {
  for (std::size_t i = 0; i < options.size(); ++i)
    if (options[i].method == method && options[i].setting == setting) return int(i);
  return -1;
}

namespace {
Result<QualityTable> tableFromAtlasJsonUnguarded(std::string_view jsonText, const TableSettings& settings);
}  // namespace

Result<QualityTable> qualityTableFromAtlasJson(std::string_view jsonText, const TableSettings& settings) {
  try {  // nlohmann's accessors throw on a value of the wrong type; the library never throws
    return tableFromAtlasJsonUnguarded(jsonText, settings);
  } catch (const nlohmann::json::exception& e) {
    return Error{std::string("quality table: a value of the atlas JSON has the wrong type (") + e.what() +
                 ")"};
  }
}

namespace {
Result<QualityTable> tableFromAtlasJsonUnguarded(std::string_view jsonText, const TableSettings& settings) {
  const nlohmann::json json = nlohmann::json::parse(jsonText.begin(), jsonText.end(), nullptr, false);
  if (json.is_discarded()) return Error{"quality table: the atlas JSON does not parse"};
  if (!json.contains("results") || !json["results"].is_array())
    return Error{"quality table: the atlas JSON has no 'results' list (tissue-sim atlas --json)"};
  std::map<std::string, double> pixelsOf;                                    // per frame: organ pixels
  std::array<double, kViewClassCount> angles = QualityTable{}.viewAngleDeg;  // none known
  if (json.contains("truth") && json["truth"].contains("frames"))
    for (const auto& f : json["truth"]["frames"]) {
      if (f.contains("frame") && f.contains("organ_pixels"))
        pixelsOf[f["frame"].get<std::string>()] = f["organ_pixels"].get<double>();
      if (f.contains("frame") && f.contains("view_angle_deg") && f["view_angle_deg"].is_number())
        if (const auto v = viewClassOfFrame(f["frame"].get<std::string>()))
          angles[std::size_t(*v)] = f["view_angle_deg"].get<double>();
    }
  struct Acc {
    std::array<double, kViewClassCount> err{}, squaredStderr{};
    std::array<bool, kViewClassCount> has{};
    double farErr = std::nan(""), farSquaredStderr = 0.0;
    std::vector<std::pair<double, double>> pxMs;
  };
  std::vector<std::pair<std::string, std::string>> order;
  std::map<std::pair<std::string, std::string>, Acc> acc;
  for (const auto& row : json["results"]) {
    for (const char* key : {"method", "setting", "frame", "ms", "rel_rms"})
      if (!row.contains(key)) return Error{std::string("quality table: a result lacks '") + key + "'"};
    const std::pair<std::string, std::string> id{row["method"].get<std::string>(),
                                                 row["setting"].get<std::string>()};
    if (!acc.count(id)) order.push_back(id);
    Acc& a = acc[id];
    const std::string frame = row["frame"].get<std::string>();
    const double ms = row["ms"].get<double>();
    if (pixelsOf.count(frame) && std::isfinite(ms)) a.pxMs.push_back({pixelsOf[frame], ms});
    const std::optional<ViewClass> view = viewClassOfFrame(frame);
    if (!view && frame != kFarFrame) continue;
    double e = row["rel_rms"].is_number() ? row["rel_rms"].get<double>() : std::nan("");
    if (settings.debiased && row.contains("rel_rms_debiased") && row["rel_rms_debiased"].is_number())
      e = row["rel_rms_debiased"].get<double>();
    if (!std::isfinite(e)) continue;
    const double stderrOfRow =
        row.contains("squared_vs_best_stderr") && row["squared_vs_best_stderr"].is_number()
            ? std::max(0.0, row["squared_vs_best_stderr"].get<double>())
            : 0.0;
    if (!view) {  // the far frame: the footprint axis, not a class
      a.farErr = e;
      a.farSquaredStderr = stderrOfRow;
      continue;
    }
    const auto v = std::size_t(*view);
    a.err[v] = e;
    a.squaredStderr[v] = stderrOfRow;
    a.has[v] = true;
  }
  QualityTable table;
  // One cost line per cost class, fitted to all its options' samples (one work measured more
  // often: the atlas's single frames of one setting vary by 2x on a shared machine). The lit
  // class keeps the plain lit row alone where the atlas has it: its intercept is the frame's
  // overhead, the reference every option is priced above, and the wrap row's noise would flatten
  // it (a line of no slope prices lit at 0 ms).
  const std::pair<std::string, std::string> plainLit{"lit", "default"};
  std::map<std::string, std::vector<std::pair<double, double>>> classSamples;
  for (const auto& id : order) {
    const std::string key = costClassKey(id.first, id.second);
    if (key == costClassKey(plainLit.first, plainLit.second) && id != plainLit && acc.count(plainLit))
      continue;
    auto& samples = classSamples[key];
    samples.insert(samples.end(), acc[id].pxMs.begin(), acc[id].pxMs.end());
  }
  std::map<std::pair<std::string, std::string>, std::pair<double, double>> lines;
  for (const auto& id : order)
    lines[id] = fitLine(classSamples[costClassKey(id.first, id.second)]);
  // Plain lit's per-pixel cost unresolved (the atlas's timing noise at its pixel counts is larger:
  // the sixteenth session's atlas fitted a negative slope): the least slope the atlas did resolve,
  // through the lit samples' centroid. An upper bound, since every method shades each pixel at
  // least as lit does, and a prior the controller's measured ratio corrects; a zero prior would
  // price lit free for good (no ratio scales 0).
  if (const auto plain = lines.find(plainLit); plain != lines.end() && plain->second.second <= 0.0) {
    double least = 0.0;
    for (const auto& [id, line] : lines)
      if (id.first != "lit" && line.second > 0.0 && (least == 0.0 || line.second < least))
        least = line.second;
    const auto& samples = classSamples[costClassKey(plainLit.first, plainLit.second)];
    if (least > 0.0 && !samples.empty()) {
      double meanPx = 0.0, meanMs = 0.0;
      for (const auto& [px, ms] : samples) {
        meanPx += px / double(samples.size());
        meanMs += ms / double(samples.size());
      }
      for (auto& [id, line] : lines)  // lit's rows share one cost class (costClassKey)
        if (id.first == "lit") line = {meanMs - least * meanPx, least};
    }
  }
  // The plain lit row's intercept (an atlas that scores the wrap term has two lit rows; without a
  // default one, the lowest lit intercept).
  if (const auto plain = lines.find(plainLit); plain != lines.end()) {
    table.frameOverheadMs = std::max(0.0, plain->second.first);
  } else {
    bool first = true;
    for (const auto& [id, line] : lines)
      if (id.first == "lit") {
        const double overhead = std::max(0.0, line.first);
        table.frameOverheadMs = first ? overhead : std::min(table.frameOverheadMs, overhead);
        first = false;
      }
  }
  for (const auto& id : order) {
    const Acc& a = acc[id];
    double sum = 0.0, sumStderr = 0.0;
    int n = 0;
    for (std::size_t v = 0; v < kViewClassCount; ++v)
      if (a.has[v]) {
        sum += a.err[v];
        sumStderr += a.squaredStderr[v];
        ++n;
      }
    if (n == 0) continue;  // no frame the controller uses
    QualityOption o;
    o.method = id.first;
    o.setting = id.second;
    for (std::size_t v = 0; v < kViewClassCount; ++v) {
      o.relRms[v] = a.has[v] ? a.err[v] : sum / n;
      o.squaredStderr[v] = a.has[v] ? a.squaredStderr[v] : sumStderr / n;
    }
    // An atlas without the oblique or low frame: the angle between its neighbours (rest and
    // grazing; oblique and grazing, the oblique frame's filled where it has none).
    const auto rest = std::size_t(ViewClass::Rest), grazing = std::size_t(ViewClass::Grazing),
               oblique = std::size_t(ViewClass::Oblique), low = std::size_t(ViewClass::Low);
    const bool hasOblique = a.has[oblique] || (a.has[rest] && a.has[grazing]);
    if (!a.has[oblique] && hasOblique) {
      o.relRms[oblique] = 0.5 * (a.err[rest] + a.err[grazing]);
      o.squaredStderr[oblique] = 0.5 * (a.squaredStderr[rest] + a.squaredStderr[grazing]);
    }
    if (!a.has[low] && hasOblique && a.has[grazing]) {
      o.relRms[low] = 0.5 * (o.relRms[oblique] + a.err[grazing]);
      o.squaredStderr[low] = 0.5 * (o.squaredStderr[oblique] + a.squaredStderr[grazing]);
    }
    o.farRelRms = a.farErr;
    o.farSquaredStderr = a.farSquaredStderr;
    o.fixedMs = std::max(0.0, lines[id].first - table.frameOverheadMs);
    o.msPerPx = lines[id].second;
    const std::string key = costClassKey(o.method, o.setting);
    const auto known = std::find(table.costClasses.begin(), table.costClasses.end(), key);
    o.costClass = int(known - table.costClasses.begin());
    if (known == table.costClasses.end()) table.costClasses.push_back(key);
    table.options.push_back(std::move(o));
  }
  if (table.options.empty())
    return Error{
        "quality table: the atlas JSON has no result on the rest, poked, close-up, oblique, low or "
        "grazing frames"};
  // No option is cheaper than plain lit: every method rasterises and shades the organ's pixels at
  // least once. A noisy fit (the wrap row's slope came out negative, its mean below lit's
  // intercept) would otherwise price an option at 0 ms, and a free option is chosen everywhere.
  if (const int lit = table.find("lit", "default"); lit >= 0) {
    const QualityOption floor = table.options[std::size_t(lit)];
    for (QualityOption& o : table.options) {
      o.fixedMs = std::max(o.fixedMs, floor.fixedMs);
      o.msPerPx = std::max(o.msPerPx, floor.msPerPx);
    }
  }
  if (settings.addWrap && table.find("lit", kWrapSetting) < 0) {
    const int lit = table.find("lit", "default");
    if (lit >= 0) {
      QualityOption wrap = table.options[std::size_t(lit)];
      wrap.setting = std::string(kWrapSetting);
      table.options.push_back(std::move(wrap));
    }
  }
  table.viewAngleDeg = angles;
  for (std::size_t v = 0; v < kViewClassCount; ++v)
    if (const auto px = pixelsOf.find(std::string(viewClassFrame(ViewClass(v)))); px != pixelsOf.end())
      table.framePx[v] = px->second;
  // The far frame counts only where every option has it (a partial row would compare options on
  // different axes).
  const bool farForAll = pixelsOf.count(std::string(kFarFrame)) &&
                         std::all_of(table.options.begin(), table.options.end(),
                                     [](const QualityOption& o) { return std::isfinite(o.farRelRms); });
  if (farForAll) table.farFramePx = pixelsOf[std::string(kFarFrame)];
  table.source = "atlas JSON";
  return table;
}
}  // namespace

Result<QualityTable> loadQualityTable(const std::filesystem::path& atlasJson, const TableSettings& settings) {
  std::ifstream in(atlasJson);
  if (!in) return Error{"quality table: cannot read " + atlasJson.string()};
  std::stringstream text;
  text << in.rdbuf();
  auto table = qualityTableFromAtlasJson(text.str(), settings);
  if (!table) return Error{atlasJson.string() + ": " + table.error().message};
  table->source = atlasJson.string();
  return table;
}

const QualityTable& defaultQualityTable() {
  static const QualityTable table = [] {
    auto parsed = qualityTableFromAtlasJson(detail::embeddedDefaultAtlas());
    QualityTable t = parsed ? std::move(*parsed) : QualityTable{};
    t.source = "data/quality/default_atlas.json (embedded)";
    return t;
  }();
  return table;
}

Result<QualityTable> qualityTableOrDefault(const std::filesystem::path& atlasJson) {
  QualityTable table = defaultQualityTable();
  if (!atlasJson.empty()) {
    auto loaded = loadQualityTable(atlasJson);
    if (!loaded) return loaded.error();
    table = std::move(*loaded);
  }
  if (table.options.empty()) return Error{"quality table " + table.source + ": it has no options"};
  return table;
}

}  // namespace tissue::quality
