#pragma once
/// \file
/// Output conventions of tissue-sim: readable text or one JSON object on stdout; an error is
/// one line on stderr ("tissue-sim <command>: <what>, <where>; <how to fix>") and exit code 1.

#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>

#include "command.h"
#include "tissue/core/result.h"
#include "tissue/studies/report.h"

namespace tissue::sim_app {

/// Prints `result` as one JSON object when `global.json`, else as "key: value" lines.
void printResult(const GlobalOptions& global, const nlohmann::json& result);

/// Prints the JSON object `jsonText` (a library report's JSON) as printResult does.
void printJsonText(const GlobalOptions& global, const std::string& jsonText);

/// Writes `report` into `dir` (tissue/studies/report.h) unless `dir` is empty: 0, or fail's
/// exit code after the error line.
int writeReportTo(const std::string& command, const std::filesystem::path& dir,
                  const studies::Report& report);

/// Prints one error line on stderr and returns the exit code to use (1).
int fail(const std::string& command, const std::string& message);

/// Prints what a library run returns, its JSON text (`json` of it: the text itself, or a member
/// holding it) as printJsonText does, or its error as fail does; returns the exit code.
template <class T, class Json = std::identity>
int printRun(const std::string& command, const GlobalOptions& global, const Result<T>& run, Json json = {}) {
  if (!run) return fail(command, run.error().message);
  printJsonText(global, std::invoke(json, *run));
  return 0;
}

/// The project's data folder: $TISSUE_DATA_DIR, else the source tree's data/.
std::filesystem::path dataDir();
/// Where build-time data (large textures) lives: $TISSUE_GENERATED_DATA_DIR, else build/data.
std::filesystem::path generatedDataDir();
/// The shared folder beside the checkout (meshes made by others): $TISSUE_SHARED_DIR or ../shared.
std::filesystem::path sharedDir();

}  // namespace tissue::sim_app
