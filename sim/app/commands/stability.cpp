// tissue-sim stability: the largest stable time step of each integrator for one mass on one
// spring, against stiffness and mass, measured by bisection and compared with the theory.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <sstream>

#include "command.h"
#include "output.h"
#include "tissue/core/atomic_file.h"
#include "tissue/core/stopwatch.h"
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

nlohmann::json toJson(const std::vector<sim::StabilityCase>& cases, double ms) {
  nlohmann::json out;
  out["model"] = "one mass on one undamped spring (rest length 10 mm, other end pinned), no gravity";
  out["units"] = {{"mass", "g"}, {"stiffness", "N/mm"}, {"dt", "s"}};
  out["cases"] = nlohmann::json::array();
  double worstSymplectic = 0.0;
  bool implicitStable = true, explicitNeverStable = true;
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
    if (c.integrator == sim::Integrator::ExplicitEuler)
      explicitNeverStable = explicitNeverStable && !c.measuredMaxDt && !c.stableAtMaxTested;
  }
  out["summary"] = {{"symplectic_and_verlet_max_relative_error", worstSymplectic},
                    {"implicit_euler_stable_at_100x", implicitStable},
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
  cmd->add_option("--out", o->out, "also write the JSON object to this file");
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
      if (auto ok = writeTextFileAtomic(o->out, result.dump(2) + "\n"); !ok) {
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
