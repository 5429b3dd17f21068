// Fuzz target: scenario files (tissue::scenario::loadScenario; docs/SCENARIOS.md).
#include "fuzz_input.h"
#include "tissue/scenario/scenario.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto file = tissue::fuzz::inputFile(data, size, ".json");
  auto scenario = tissue::scenario::loadScenario(file);
  if (!scenario) tissue::fuzz::checkRefusal(scenario.error().message, file);
  return 0;
}
