// tissue-sim stability: the largest stable time step of each integrator for one mass on one
// spring, against stiffness and mass, measured by bisection and compared with the theory.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "command.h"
#include "output.h"
#include "tissue/core/atomic_file.h"
#include "tissue/core/stopwatch.h"
#include "tissue/inspect/chart.h"
#include "tissue/sim/stability_study.h"

namespace tissue::sim_app {
namespace {

nlohmann::json optionalJson(const std::optional<double>& value) {
  return value ? nlohmann::json(*value) : nlohmann::json(nullptr);
}

std::string verdict(const sim::StabilityCase& c) {
  if (c.stableAtMaxTested) return "stable up to the largest step tested";
  if (!c.measuredMaxDt) return "unstable at every step tested";
  return "limit found";
}

std::string formatDt(const std::optional<double>& dt) {
  if (!dt) return "-";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g", *dt * 1e3);
  return buffer;
}

/// The cases as a markdown table (time steps in ms).
std::string markdownTable(const std::vector<sim::StabilityCase>& cases) {
  std::ostringstream out;
  out << "| integrator | mass (g) | stiffness (N/mm) | 2 sqrt(m/k) (ms) | theory max dt (ms) | measured max "
         "dt (ms)"
         " | measured / theory | verdict |\n";
  out << "|---|---|---|---|---|---|---|---|\n";
  for (const auto& c : cases) {
    std::string ratio = "-";
    if (c.measuredMaxDt && c.theoryMaxDt) {
      char buffer[32];
      std::snprintf(buffer, sizeof buffer, "%.5f", *c.measuredMaxDt / *c.theoryMaxDt);
      ratio = buffer;
    }
    out << "| " << sim::integratorName(c.integrator) << " | " << c.mass << " | " << c.stiffness << " | "
        << formatDt(c.referenceDt) << " | " << formatDt(c.theoryMaxDt) << " | " << formatDt(c.measuredMaxDt)
        << " | " << ratio << " | " << verdict(c) << " |\n";
  }
  return out.str();
}

/// The chart's data: per integrator and mass, max dt / 2 sqrt(m/k) against stiffness; a case
/// stable up to the largest step tested is drawn at that bound (a lower bound on its limit).
struct ChartData {
  std::vector<std::string> labels;
  std::vector<std::vector<double>> x, y;
};

ChartData chartData(const std::vector<sim::StabilityCase>& cases) {
  ChartData d;
  for (const auto& c : cases) {
    const std::optional<double> dt =
        c.stableAtMaxTested ? std::optional<double>(c.maxDtTested) : c.measuredMaxDt;
    if (!dt) continue;  // explicit Euler: no stable step at all
    char label[96];
    std::snprintf(label, sizeof label, "%s, m = %g g%s",
                  std::string(sim::integratorName(c.integrator)).c_str(), c.mass,
                  c.stableAtMaxTested ? " (stable at every step tested)" : "");
    std::size_t k = 0;
    while (k < d.labels.size() && d.labels[k] != label)
      ++k;
    if (k == d.labels.size()) d.labels.push_back(label), d.x.emplace_back(), d.y.emplace_back();
    d.x[k].push_back(c.stiffness);
    d.y[k].push_back(*dt / c.referenceDt);
  }
  return d;
}

/// DIR/stability.md (the table), DIR/stability.json, DIR/stability_chart.csv (the chart's
/// series) and DIR/stability.png (the chart).
Result<void> writeOutputs(const std::filesystem::path& dir, const std::string& table,
                          const nlohmann::json& result, const std::vector<sim::StabilityCase>& cases) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) return Error{"cannot create the folder " + dir.string() + ": " + ec.message()};
  const std::string md =
      "# Stability study\n\nOne undamped mass on one spring (rest length 10 mm, other end "
      "pinned); time steps in ms; reference 2 sqrt(m/k).\n\n" +
      table + "\n![max dt / 2 sqrt(m/k) against stiffness](stability.png)\n";
  if (auto ok = writeTextFileAtomic(dir / "stability.md", md); !ok) return ok;
  if (auto ok = writeTextFileAtomic(dir / "stability.json", result.dump(2) + "\n"); !ok) return ok;
  const ChartData d = chartData(cases);
  std::ostringstream csv;
  csv << "series,stiffness_n_per_mm,max_dt_over_reference\n";
  for (std::size_t k = 0; k < d.labels.size(); ++k)
    for (std::size_t p = 0; p < d.x[k].size(); ++p)
      csv << '"' << d.labels[k] << "\"," << d.x[k][p] << ',' << d.y[k][p] << "\n";
  if (auto ok = writeTextFileAtomic(dir / "stability_chart.csv", csv.str()); !ok) return ok;
  std::vector<inspect::ChartSeries> series;
  for (std::size_t k = 0; k < d.labels.size(); ++k)
    series.push_back({d.labels[k], d.x[k], d.y[k], true});
  return inspect::writeLineChart(dir / "stability.png",
                                 {.title = "Largest stable time step, one mass on one spring",
                                  .xLabel = "stiffness k (N/mm)",
                                  .yLabel = "max stable dt / 2 sqrt(m/k)",
                                  .logX = true,
                                  .logY = true},
                                 series);
}

nlohmann::json toJson(const std::vector<sim::StabilityCase>& cases, double ms) {
  nlohmann::json out;
  out["model"] = "one mass on one undamped spring (rest length 10 mm, other end pinned), no gravity";
  out["units"] = {{"mass", "g"}, {"stiffness", "N/mm"}, {"dt", "s"}};
  out["cases"] = nlohmann::json::array();
  double worstSymplectic = 0.0;
  bool implicitStable = true, fastStable = true, explicitNeverStable = true;
  for (const auto& c : cases) {
    nlohmann::json j;
    j["integrator"] = sim::integratorName(c.integrator);
    j["mass"] = c.mass;
    j["stiffness"] = c.stiffness;
    j["reference_dt"] = c.referenceDt;
    j["theory_max_dt"] = optionalJson(c.theoryMaxDt);
    j["measured_max_dt"] = optionalJson(c.measuredMaxDt);
    j["measured_over_theory"] = (c.measuredMaxDt && c.theoryMaxDt)
                                    ? nlohmann::json(*c.measuredMaxDt / *c.theoryMaxDt)
                                    : nlohmann::json(nullptr);
    j["min_dt_tested"] = c.minDtTested;
    j["max_dt_tested"] = c.maxDtTested;
    j["stable_at_max_dt_tested"] = c.stableAtMaxTested;
    j["verdict"] = verdict(c);
    j["trials"] = c.trials;
    out["cases"].push_back(j);
    if (c.theoryMaxDt) {
      const double error = c.measuredMaxDt ? std::abs(*c.measuredMaxDt / *c.theoryMaxDt - 1.0) : 1.0;
      worstSymplectic = std::max(worstSymplectic, error);
    }
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
                    {"study_ms", ms}};
  return out;
}

}  // namespace

void registerStabilityCommand(CLI::App& app, const GlobalOptions& global, int& exitCode) {
  struct Options {
    std::vector<double> masses{0.1, 1.0, 10.0};
    std::vector<double> stiffnesses{0.01, 0.1, 1.0};
    std::string markdown;
    std::string out;
  };
  auto o = std::make_shared<Options>();
  auto* cmd = app.add_subcommand(
      "stability", "largest stable time step of each integrator vs stiffness and mass, against theory");
  cmd->add_option("--masses", o->masses, "masses in g (default 0.1 1 10)");
  cmd->add_option("--stiffnesses", o->stiffnesses, "spring stiffnesses in N/mm (default 0.01 0.1 1)");
  cmd->add_option("--markdown", o->markdown, "also write the table as markdown to this file");
  cmd->add_option("--out", o->out,
                  "also write DIR/stability.md (table), stability.json, stability_chart.csv and the chart");
  cmd->callback([o, &global, &exitCode] {
    for (double m : o->masses)
      if (!(m > 0.0) || !std::isfinite(m)) {
        exitCode = fail("stability", "--masses: every mass must be a positive number of grams");
        return;
      }
    for (double k : o->stiffnesses)
      if (!(k > 0.0) || !std::isfinite(k)) {
        exitCode = fail("stability", "--stiffnesses: every stiffness must be a positive number of N/mm");
        return;
      }
    sim::StabilityStudyConfig config;
    config.masses = o->masses;
    config.stiffnesses = o->stiffnesses;
    Stopwatch clock;
    const auto cases = sim::runStabilityStudy(config);
    const nlohmann::json result = toJson(cases, clock.elapsedMs());
    const std::string table = markdownTable(cases);
    if (!o->markdown.empty())
      if (auto ok = writeTextFileAtomic(o->markdown, table); !ok) {
        exitCode = fail("stability", ok.error().message);
        return;
      }
    if (!o->out.empty())
      if (auto ok = writeOutputs(o->out, table, result, cases); !ok) {
        exitCode = fail("stability", ok.error().message);
        return;
      }
    if (global.json) {
      printResult(global, result);
    } else {
      std::cout << table << "\n";
      printResult(global, {{"summary", result["summary"]}});
    }
    exitCode = 0;
  });
}

}  // namespace tissue::sim_app
