// Option groups several commands share (cli_options.h).
#include "cli_options.h"

#include <iostream>

#include "output.h"

namespace tissue::sim_app {

void addImageSizeOptions(CLI::App* cmd, int& width, int& height) {
  cmd->add_option("--width", width, "image width, pixels (default " + std::to_string(width) + ")");
  cmd->add_option("--height", height, "image height, pixels (default " + std::to_string(height) + ")");
}

std::filesystem::path meshOrDefault(const std::string& file) {
  return file.empty() ? dataDir() / "meshes" / "liver.obj" : std::filesystem::path(file);
}

std::filesystem::path scenarioOrDefault(const std::string& file) {
  return file.empty() ? dataDir() / "scenarios" / "liver_poke_grasp.json" : std::filesystem::path(file);
}

Result<scenario::Scenario> loadScenarioFile(const std::string& command, const std::string& file) {
  auto parsed = scenario::loadScenario(file, {.sharedMeshesDir = sharedDir() / "meshes"});
  if (parsed)
    for (const std::string& warning : parsed->warnings)
      std::cerr << "tissue-sim " << command << ": warning: " << warning << "\n";
  return parsed;
}

Result<sim::Integrator> parseIntegratorOption(const std::string& option, const std::string& name) {
  if (auto integrator = sim::parseIntegrator(name)) return *integrator;
  return Error{option + ": unknown integrator \"" + name +
               "\"; give explicit-euler, symplectic-euler, verlet, implicit-euler or fast-mass-spring"};
}

}  // namespace tissue::sim_app
