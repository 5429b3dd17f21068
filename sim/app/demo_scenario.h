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
  std::string scenarioFile;             ///< empty: data/scenarios/liver_poke_grasp.json (docs/SCENARIOS.md)
  std::string meshFile;                 ///< empty: the scenario's mesh; must have UVs and a material file
  int frames = 0;                       ///< 0: the scenario's frames
  int imageEvery = 100;                 ///< the loop's rendered frame is written every this many frames
  std::filesystem::path recordSession;  ///< non-empty: write the run as a session (scene::SessionRecorder)
  int loopWidth = 480;                  ///< pixels of the frame the loop renders every frame
  int loopHeight = 360;                 ///< pixels
  int width = 960;
  int height = 720;
};

/// Runs the scenario and returns the report (also written to outDir/report.json and .md).
Result<nlohmann::json> runDemo(const DemoOptions& options);

}  // namespace tissue::sim_app
