#pragma once
/// \file
/// Output conventions of tissue-sim: readable text or one JSON object on stdout; an error is
/// one line on stderr ("tissue-sim <command>: <what>, <where>; <how to fix>") and exit code 1.

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "command.h"

namespace tissue::sim_app {

/// Prints `result` as one JSON object when `global.json`, else as "key: value" lines.
void printResult(const GlobalOptions& global, const nlohmann::json& result);

/// Prints one error line on stderr and returns the exit code to use (1).
int fail(const std::string& command, const std::string& message);

/// The project's data folder: $TISSUE_DATA_DIR, else the source tree's data/.
std::filesystem::path dataDir();
/// Where build-time data (large textures) lives: $TISSUE_GENERATED_DATA_DIR, else build/data.
std::filesystem::path generatedDataDir();
/// The shared folder beside the checkout (meshes made by others): $TISSUE_SHARED_DIR or ../shared.
std::filesystem::path sharedDir();

}  // namespace tissue::sim_app
