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
  std::string meshFile;  ///< empty: data/meshes/liver.obj
  int frames = 60;
  double pokeFraction = 0.05;  ///< fraction of vertices the instrument moves
  float pokeDepthMm = 12.0f;   ///< deepest indentation, mm
  int width = 960;
  int height = 720;
};

/// Runs the scenario and returns the report (also written to outDir/report.json and .md).
Result<nlohmann::json> runDemo(const DemoOptions& options);

}  // namespace tissue::sim_app
