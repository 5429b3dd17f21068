// The one-spring stability study's report (stability_report.h).
#include "tissue/studies/stability_report.h"

#include <algorithm>
#include <cmath>

#include "json_text.h"
#include "tissue/core/stopwatch.h"

namespace tissue::studies {
namespace {

using detail::optionalJson;

std::string ms(const std::optional<double>& dtS) {
  return dtS ? general(*dtS * 1e3) : "-";
}

std::optional<double> ratio(const sim::StabilityCase& c) {
  if (c.measuredMaxDt && c.theoryMaxDt) return *c.measuredMaxDt / *c.theoryMaxDt;
  return std::nullopt;
}

nlohmann::json toJson(const std::vector<sim::StabilityCase>& cases, double studyMs) {
  nlohmann::json out;
  out["model"] = "one mass on one undamped spring (rest length 10 mm, other end pinned), no gravity";
  out["units"] = {{"mass", "g"}, {"stiffness", "N/mm"}, {"dt", "s"}};
  out["cases"] = nlohmann::json::array();
  double worstSymplectic = 0.0;
  bool implicitStable = true, fastStable = true, explicitNeverStable = true;
  for (const auto& c : cases) {
    out["cases"].push_back({{"integrator", sim::integratorName(c.integrator)},
                            {"mass", c.mass},
                            {"stiffness", c.stiffness},
                            {"reference_dt", c.referenceDt},
                            {"theory_max_dt", optionalJson(c.theoryMaxDt)},
                            {"measured_max_dt", optionalJson(c.measuredMaxDt)},
                            {"measured_over_theory", optionalJson(ratio(c))},
                            {"min_dt_tested", c.minDtTested},
                            {"max_dt_tested", c.maxDtTested},
                            {"stable_at_max_dt_tested", c.stableAtMaxTested},
                            {"verdict", stabilityVerdict(c)},
                            {"trials", c.trials}});
    if (c.theoryMaxDt)
      worstSymplectic = std::max(worstSymplectic, ratio(c) ? std::abs(*ratio(c) - 1.0) : 1.0);
    if (c.integrator == sim::Integrator::ImplicitEuler)
      implicitStable = implicitStable && c.stableAtMaxTested;
    if (c.integrator == sim::Integrator::FastMassSpring) fastStable = fastStable && c.stableAtMaxTested;
    if (c.integrator == sim::Integrator::ExplicitEuler)
      explicitNeverStable = explicitNeverStable && !c.measuredMaxDt && !c.stableAtMaxTested;
  }
  out["summary"] = {{"symplectic_and_verlet_max_relative_error", worstSymplectic},
                    {"implicit_euler_stable_at_100x", implicitStable},
                    {"fast_mass_spring_stable_at_100x", fastStable},
                    {"explicit_euler_unstable_at_every_dt", explicitNeverStable},
                    {"study_ms", studyMs}};
  return out;
}

}  // namespace

std::string stabilityVerdict(const sim::StabilityCase& c) {
  if (c.stableAtMaxTested) return "stable up to the largest step tested";
  if (!c.measuredMaxDt) return "unstable at every step tested";
  return "limit found";
}

Table stabilityTable(const std::vector<sim::StabilityCase>& cases) {
  Table t{{"integrator", "mass (g)", "stiffness (N/mm)", "2 sqrt(m/k) (ms)", "theory max dt (ms)",
           "measured max dt (ms)", "measured / theory", "verdict"},
          {}};
  for (const auto& c : cases)
    t.rows.push_back({std::string(sim::integratorName(c.integrator)), general(c.mass), general(c.stiffness),
                      ms(c.referenceDt), ms(c.theoryMaxDt), ms(c.measuredMaxDt),
                      ratio(c) ? fixed(*ratio(c), 5) : "-", stabilityVerdict(c)});
  return t;
}

std::vector<inspect::ChartSeries> stabilityChartSeries(const std::vector<sim::StabilityCase>& cases) {
  std::vector<inspect::ChartSeries> out;
  for (const auto& c : cases) {
    const std::optional<double> dt =
        c.stableAtMaxTested ? std::optional<double>(c.maxDtTested) : c.measuredMaxDt;
    if (!dt) continue;  // explicit Euler: no stable step at all
    const std::string label = std::string(sim::integratorName(c.integrator)) + ", m = " + general(c.mass) +
                              " g" + (c.stableAtMaxTested ? " (stable at every step tested)" : "");
    auto s = std::find_if(out.begin(), out.end(), [&](const auto& series) { return series.label == label; });
    if (s == out.end()) s = out.insert(out.end(), inspect::ChartSeries{label, {}, {}, true});
    s->x.push_back(c.stiffness);
    s->y.push_back(*dt / c.referenceDt);
  }
  return out;
}

StabilityReport runStabilityReport(const sim::StabilityStudyConfig& config) {
  StabilityReport r;
  Stopwatch clock;
  r.cases = sim::runStabilityStudy(config);
  r.studyMs = clock.elapsedMs();
  r.markdown = markdownTable(stabilityTable(r.cases));
  r.json = detail::jsonText(toJson(r.cases, r.studyMs));
  const auto series = stabilityChartSeries(r.cases);
  Table csv{{"series", "stiffness_n_per_mm", "max_dt_over_reference"}, {}};
  for (const auto& s : series)
    for (std::size_t p = 0; p < s.x.size(); ++p)
      csv.rows.push_back({s.label, general(s.x[p]), general(s.y[p])});
  r.report.add(
      "stability.md",
      "# Stability study\n\nOne undamped mass on one spring (rest length 10 mm, other end pinned); time "
      "steps in ms; reference 2 sqrt(m/k).\n\n" +
          r.markdown + "\n![max dt / 2 sqrt(m/k) against stiffness](stability.png)\n");
  r.report.add("stability.json", r.json);
  r.report.add("stability_chart.csv", csvTable(csv));
  inspect::ChartSettings chart;  // named, not a temporary: GCC 12 warns of a maybe-uninitialized copy
  chart.title = "Largest stable time step, one mass on one spring";
  chart.xLabel = "stiffness k (N/mm)";
  chart.yLabel = "max stable dt / 2 sqrt(m/k)";
  chart.logX = chart.logY = true;
  r.report.charts.push_back({"stability.png", chart, series});
  return r;
}

}  // namespace tissue::studies
