#pragma once
/// \file
/// Option groups and option values several tissue-sim commands share, each written once: the
/// image size, the project's default organ and scenario, a scenario file with its warnings, an
/// integrator by name. CLI11 stays in the app; the values land in the library's plain structs.

#include <CLI/CLI.hpp>
#include <filesystem>
#include <string>

#include "tissue/core/result.h"
#include "tissue/scenario/scenario.h"
#include "tissue/sim/integrators.h"

namespace tissue::sim_app {

/// Adds --width and --height (pixels) to `cmd`, their help naming the defaults they now hold:
/// "image width, pixels (default W)".
void addImageSizeOptions(CLI::App* cmd, int& width, int& height);

/// `file`, or the project's organ when empty: data/meshes/liver.obj.
std::filesystem::path meshOrDefault(const std::string& file);
/// `file`, or the project's scenario when empty: data/scenarios/liver_poke_grasp.json.
std::filesystem::path scenarioOrDefault(const std::string& file);

/// The scenario `file` with the shared meshes (scenario::loadScenario); its warnings (e.g. a
/// Poisson ratio springs cannot realise) as `command`'s warning lines on stderr.
Result<scenario::Scenario> loadScenarioFile(const std::string& command, const std::string& file);

/// The integrator `name` of option `option` ("--integrator"); the error lists the names.
Result<sim::Integrator> parseIntegratorOption(const std::string& option, const std::string& name);

}  // namespace tissue::sim_app
