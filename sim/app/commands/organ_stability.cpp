// tissue-sim organ-stability: the stability study moved from one spring to the organ. For each
// integrator and Young's modulus, the largest frame step at which the default scenario (the
// volumetric liver under its scripted poke) runs without divergence, the degrade off; and what
// each integrator costs per 60 Hz frame to stay stable. Table, JSON and two charts.
#include <cmath>
#include <filesystem>
#include <sstream>

#include "command.h"
#include "loop_setup.h"
#include "output.h"
#include "tissue/core/atomic_file.h"
#include "tissue/inspect/chart.h"
#include "tissue/scenario/organ_stability.h"

namespace tissue::sim_app {
namespace {

struct OrganStabilityOptions {
  std::string scenario;
  std::vector<double> moduli{2.0, 5.0, 20.0, 80.0};
  double windowS = 3.5;
  std::filesystem::path out;
};

nlohmann::json rowJson(const scenario::OrganStabilityRow& r) {
  auto optional = [](const auto& v) { return v ? nlohmann::json(*v) : nlohmann::json(nullptr); };
  return {
      {"integrator", sim::integratorName(r.integrator)},
      {"youngs_modulus_kpa", r.youngsModulusKpa},
      {"max_stable_step_ms",
       r.maxStableStepS ? nlohmann::json(*r.maxStableStepS * 1e3) : nlohmann::json(nullptr)},
      {"stable_at_max_tested", r.stableAtMaxTested},
      {"substeps_per_60hz_frame", optional(r.substepsPerFrame)},
      {"ms_per_frame_median",
       r.substepsPerFrame ? nlohmann::json(r.msPerFrameMedian) : nlohmann::json(nullptr)},
      {"ms_per_frame_max", r.substepsPerFrame ? nlohmann::json(r.msPerFrameMax) : nlohmann::json(nullptr)},
      {"trials", r.trials}};
}

std::string markdown(const std::vector<scenario::OrganStabilityRow>& rows, double maxStepMs) {
  std::ostringstream md;
  md << "| integrator | E (kPa) | largest stable frame step (ms) | substeps per 1/60 s frame | ms per frame "
        "(median) | ms per frame (max) |\n|---|---|---|---|---|---|\n";
  for (const auto& r : rows) {
    md << "| " << sim::integratorName(r.integrator) << " | " << r.youngsModulusKpa << " | ";
    if (r.stableAtMaxTested)
      md << ">= " << maxStepMs << " (stable at every step tried)";
    else if (r.maxStableStepS)
      md << rounded(*r.maxStableStepS * 1e3);
    else
      md << "unstable at every step tried";
    md << " | ";
    if (r.substepsPerFrame)
      md << *r.substepsPerFrame << " | " << rounded(r.msPerFrameMedian) << " | " << rounded(r.msPerFrameMax);
    else
      md << "- | - | -";
    md << " |\n";
  }
  return md.str();
}

/// Series per integrator: y(row) against E, for the rows where `y` gives a value.
template <class Y>
std::vector<inspect::ChartSeries> seriesBy(const std::vector<scenario::OrganStabilityRow>& rows,
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

Result<nlohmann::json> run(const OrganStabilityOptions& o) {
  const auto file = o.scenario.empty() ? dataDir() / "scenarios" / "liver_poke_grasp.json"
                                       : std::filesystem::path(o.scenario);
  auto base = scenario::loadScenario(file, {.sharedMeshesDir = sharedDir() / "meshes"});
  if (!base) return base.error();
  scenario::OrganStabilityConfig config;
  config.youngsModuliKpa = o.moduli;
  config.windowS = o.windowS;
  auto rows = scenario::runOrganStabilityStudy(*base, config);
  if (!rows) return rows.error();
  nlohmann::json j{{"scenario", file.string()},
                   {"window_s", config.windowS},
                   {"min_step_ms", config.minStepS * 1e3},
                   {"max_step_ms", config.maxStepS * 1e3},
                   {"rows", nlohmann::json::array()}};
  for (const auto& r : *rows)
    j["rows"].push_back(rowJson(r));
  if (!o.out.empty()) {
    const std::string md = markdown(*rows, config.maxStepS * 1e3);
    if (auto w = writeTextFileAtomic(o.out / "organ_stability.md", md); !w) return w.error();
    if (auto w = writeTextFileAtomic(o.out / "organ_stability.json", j.dump(2) + "\n"); !w) return w.error();
    // Chart 1: the limits of the conditionally stable integrators (the others have none).
    const auto limits = seriesBy(*rows, config.integrators, [](const scenario::OrganStabilityRow& r) {
      return r.maxStableStepS && !r.stableAtMaxTested ? std::optional<double>(*r.maxStableStepS * 1e3)
                                                      : std::nullopt;
    });
    // Chart 2: what staying stable at 60 Hz costs, every integrator that managed it.
    const auto costs = seriesBy(*rows, config.integrators, [](const scenario::OrganStabilityRow& r) {
      return r.substepsPerFrame ? std::optional<double>(r.msPerFrameMedian) : std::nullopt;
    });
    nlohmann::json charts = nlohmann::json::array();
    const std::pair<const char*, const std::vector<inspect::ChartSeries>*> plan[] = {
        {"organ_stability_limits.png", &limits}, {"organ_stability_cost.png", &costs}};
    for (const auto& [name, series] : plan) {
      if (series->empty()) continue;
      inspect::ChartSettings settings;
      const bool isLimits = series == &limits;
      settings.title = isLimits ? "Largest stable frame step on the liver (scripted poke, no degrade)"
                                : "Cost of a stable 1/60 s frame on the liver (scripted poke)";
      settings.xLabel = "Young's modulus E (kPa)";
      settings.yLabel = isLimits ? "largest stable step (ms)" : "ms per frame (median)";
      settings.logX = settings.logY = true;
      if (auto c = inspect::writeLineChart(o.out / name, settings, *series); c)
        charts.push_back(name);
      else
        j["chart_skipped"] = c.error().message;
    }
    j["charts"] = charts;
    j["out"] = o.out.string();
  }
  return j;
}

}  // namespace

void registerOrganStabilityCommand(CLI::App& app, const GlobalOptions& global, int& exitCode) {
  auto o = std::make_shared<OrganStabilityOptions>();
  auto* cmd = app.add_subcommand(
      "organ-stability", "the largest stable frame step and the 60 Hz cost of each integrator on the organ");
  cmd->add_option("--scenario", o->scenario, "scenario with a tissue block (default: the data liver's)");
  cmd->add_option("--moduli", o->moduli, "Young's moduli in kPa (default 2 5 20 80)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--window", o->windowS,
                  "simulated seconds per trial (default 3.5: through the deepest poke)")
      ->check(CLI::Range(0.05, 60.0));
  cmd->add_option("--out", o->out, "folder for organ_stability.md, .json and the charts");
  cmd->callback([o, &global, &exitCode] {
    auto r = run(*o);
    if (!r) {
      exitCode = fail("organ-stability", r.error().message);
      return;
    }
    printResult(global, *r);
  });
}

}  // namespace tissue::sim_app
