#pragma once
/// \file
/// The default headless scenario, as a function the command and the tests can call.

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "tissue/core/result.h"

namespace tissue::sim_app {

/// Settings of the demo scenario (plain struct with defaults).
struct DemoOptions {
  std::filesystem::path outDir;
  std::string scenarioFile;  ///< empty: data/scenarios/liver_poke_grasp.json (docs/SCENARIOS.md)
  std::string meshFile;      ///< empty: the scenario's mesh; must have UVs and a material file
  int frames = 0;            ///< 0: the scenario's frames
  int width = 960;
  int height = 720;
};

/// Runs the scenario and returns the report (also written to outDir/report.json and .md).
Result<nlohmann::json> runDemo(const DemoOptions& options);

}  // namespace tissue::sim_app
