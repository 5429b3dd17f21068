#include "loop_setup.h"

#include <cmath>

#include "output.h"
#include "tissue/core/statistics.h"

namespace tissue::sim_app {

Result<LoopOrgan> loadLoopOrgan(const std::filesystem::path& scenarioFile, const std::string& meshOverride) {
  auto parsed = scenario::loadScenario(scenarioFile, {.sharedMeshesDir = sharedDir() / "meshes"});
  if (!parsed) return parsed.error();
  if (!meshOverride.empty()) parsed->mesh = meshOverride;
  auto assets = scene::loadOrganAssets(organSourceFor(parsed->mesh, float(parsed->meshScaleToMm)));
  if (!assets) return assets.error();
  LoopOrgan organ{.scenario = std::move(*parsed), .assets = std::move(*assets)};
  return organ;
}

void PhaseSamples::add(const scene::LoopFrame& f) {
  const double values[] = {f.ms.simulateMs,   f.mesh.gatherMs, f.mesh.normalsMs, f.mesh.planesMs,
                           f.mesh.tangentsMs, f.ms.uploadMs,   f.ms.renderMs,    f.ms.totalMs};
  for (std::size_t i = 0; i < phases.size(); ++i)
    phases[i].second.push_back(values[i]);
}

double rounded(double x) {
  if (x == 0.0 || !std::isfinite(x)) return x;
  const double scale = std::pow(10.0, 2 - std::floor(std::log10(std::abs(x))));
  return std::round(x * scale) / scale;
}

nlohmann::json phaseReport(const PhaseSamples& samples) {
  nlohmann::json j = nlohmann::json::array();
  for (const auto& [name, values] : samples.phases) {
    const auto s = summarizeSamples(values);
    j.push_back({{"phase", name},
                 {"median_ms", rounded(s.median)},
                 {"p99_ms", rounded(s.p99)},
                 {"max_ms", rounded(s.max)}});
  }
  return j;
}

}  // namespace tissue::sim_app
