#include "output.h"

#include <cstdlib>
#include <iostream>

namespace tissue::sim_app {
namespace {

std::filesystem::path fromEnv(const char* name, const char* fallback) {
  if (const char* v = std::getenv(name); v && *v) return v;
  return fallback;
}

void printText(const nlohmann::json& value, const std::string& indent) {
  for (const auto& [key, item] : value.items()) {
    if (item.is_object()) {
      std::cout << indent << key << ":\n";
      printText(item, indent + "  ");
    } else if (item.is_string()) {
      std::cout << indent << key << ": " << item.get<std::string>() << "\n";
    } else {
      std::cout << indent << key << ": " << item.dump() << "\n";
    }
  }
}

}  // namespace

void printResult(const GlobalOptions& global, const nlohmann::json& result) {
  if (global.json) {
    std::cout << result.dump(2) << std::endl;
  } else {
    printText(result, "");
  }
}

void printJsonText(const GlobalOptions& global, const std::string& jsonText) {
  printResult(global, nlohmann::json::parse(jsonText));
}

int writeReportTo(const std::string& command, const std::filesystem::path& dir,
                  const studies::Report& report) {
  if (dir.empty()) return 0;
  if (auto ok = studies::writeReport(dir, report); !ok) return fail(command, ok.error().message);
  return 0;
}

int fail(const std::string& command, const std::string& message) {
  std::cerr << "tissue-sim " << command << ": " << message << std::endl;
  return 1;
}

std::filesystem::path dataDir() {
  return fromEnv("TISSUE_DATA_DIR", TISSUE_DEFAULT_DATA_DIR);
}
std::filesystem::path generatedDataDir() {
  return fromEnv("TISSUE_GENERATED_DATA_DIR", TISSUE_DEFAULT_GENERATED_DATA_DIR);
}

std::filesystem::path sharedDir() {
  return fromEnv("TISSUE_SHARED_DIR", TISSUE_DEFAULT_SHARED_DIR);
}

}  // namespace tissue::sim_app
