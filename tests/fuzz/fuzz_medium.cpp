// Fuzz target: layered-medium files (tissue::optics::loadMediumFile; the profile command's --medium).
#include "fuzz_input.h"
#include "tissue/optics/medium.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto file = tissue::fuzz::inputFile(data, size, ".json");
  auto medium = tissue::optics::loadMediumFile(file);
  if (!medium) tissue::fuzz::checkRefusal(medium.error().message, file);
  return 0;
}
