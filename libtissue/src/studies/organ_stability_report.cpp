// The organ stability study's report (organ_stability_report.h).
#include "tissue/studies/organ_stability_report.h"

#include "json_text.h"

namespace tissue::studies {
namespace {

using detail::optionalJson;
using scenario::OrganStabilityRow;

nlohmann::json rowJson(const OrganStabilityRow& r) {
  const auto perFrame = [&r](double ms) {
    return r.substepsPerFrame ? nlohmann::json(ms) : nlohmann::json(nullptr);
  };
  return {{"integrator", sim::integratorName(r.integrator)},
          {"youngs_modulus_kpa", r.youngsModulusKpa},
          {"max_stable_step_ms",
           r.maxStableStepS ? nlohmann::json(*r.maxStableStepS * 1e3) : nlohmann::json(nullptr)},
          {"stable_at_max_tested", r.stableAtMaxTested},
          {"substeps_per_60hz_frame", optionalJson(r.substepsPerFrame)},
          {"ms_per_frame_median", perFrame(r.msPerFrameMedian)},
          {"ms_per_frame_max", perFrame(r.msPerFrameMax)},
          {"trials", r.trials}};
}

/// Series per integrator: y(row) against E, for the rows where `y` gives a value.
template <class Y>
std::vector<inspect::ChartSeries> seriesBy(const std::vector<OrganStabilityRow>& rows,
                                           const std::vector<sim::Integrator>& integrators, Y y) {
  std::vector<inspect::ChartSeries> out;
  for (sim::Integrator integrator : integrators) {
    inspect::ChartSeries s{
        .label = std::string(sim::integratorName(integrator)), .x = {}, .y = {}, .lines = true};
    for (const auto& r : rows)
      if (r.integrator == integrator)
        if (auto v = y(r)) s.x.push_back(r.youngsModulusKpa), s.y.push_back(*v);
    if (!s.x.empty()) out.push_back(std::move(s));
  }
  return out;
}

}  // namespace

Table organStabilityTable(const std::vector<OrganStabilityRow>& rows, double maxStepMs) {
  Table t{{"integrator", "E (kPa)", "largest stable frame step (ms)", "substeps per 1/60 s frame",
           "ms per frame (median)", "ms per frame (max)"},
          {}};
  for (const auto& r : rows) {
    std::vector<std::string> row{std::string(sim::integratorName(r.integrator)), general(r.youngsModulusKpa)};
    if (r.stableAtMaxTested)
      row.push_back(">= " + general(maxStepMs) + " (stable at every step tried)");
    else if (r.maxStableStepS)
      row.push_back(general(*r.maxStableStepS * 1e3, 3));
    else
      row.push_back("unstable at every step tried");
    if (r.substepsPerFrame)
      row.insert(row.end(), {std::to_string(*r.substepsPerFrame), general(r.msPerFrameMedian, 3),
                             general(r.msPerFrameMax, 3)});
    else
      row.insert(row.end(), {"-", "-", "-"});
    t.rows.push_back(row);
  }
  return t;
}

Result<OrganStabilityReport> runOrganStabilityReport(const std::filesystem::path& scenarioFile,
                                                     const scenario::ScenarioPaths& paths,
                                                     const scenario::OrganStabilityConfig& config) {
  auto base = scenario::loadScenario(scenarioFile, paths);
  if (!base) return base.error();
  auto rows = scenario::runOrganStabilityStudy(*base, config);
  if (!rows) return rows.error();
  OrganStabilityReport r{std::move(*rows), {}, {}};
  nlohmann::json j{{"scenario", scenarioFile.string()},
                   {"window_s", config.windowS},
                   {"min_step_ms", config.minStepS * 1e3},
                   {"max_step_ms", config.maxStepS * 1e3},
                   {"rows", nlohmann::json::array()}};
  for (const auto& row : r.rows)
    j["rows"].push_back(rowJson(row));
  r.json = detail::jsonText(j);
  r.report.add("organ_stability.md", markdownTable(organStabilityTable(r.rows, config.maxStepS * 1e3)));
  r.report.add("organ_stability.json", r.json);
  // The limits of the conditionally stable integrators (the others have none), and what staying
  // stable at 60 Hz costs, every integrator that managed it.
  auto limits = seriesBy(r.rows, config.integrators, [](const OrganStabilityRow& row) {
    return row.maxStableStepS && !row.stableAtMaxTested ? std::optional<double>(*row.maxStableStepS * 1e3)
                                                        : std::nullopt;
  });
  auto costs = seriesBy(r.rows, config.integrators, [](const OrganStabilityRow& row) {
    return row.substepsPerFrame ? std::optional<double>(row.msPerFrameMedian) : std::nullopt;
  });
  inspect::ChartSettings chart;  // named, not a temporary: GCC 12 warns of a maybe-uninitialized copy
  chart.xLabel = "Young's modulus E (kPa)";
  chart.logX = chart.logY = true;
  if (!limits.empty()) {
    chart.title = "Largest stable frame step on the liver (scripted poke, no degrade)";
    chart.yLabel = "largest stable step (ms)";
    r.report.charts.push_back({"organ_stability_limits.png", chart, std::move(limits)});
  }
  if (!costs.empty()) {
    chart.title = "Cost of a stable 1/60 s frame on the liver (scripted poke)";
    chart.yLabel = "ms per frame (median)";
    r.report.charts.push_back({"organ_stability_cost.png", chart, std::move(costs)});
  }
  return r;
}

}  // namespace tissue::studies
