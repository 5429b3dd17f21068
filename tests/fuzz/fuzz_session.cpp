// Fuzz target: recorded sessions (tissue::scene::loadSession; docs/SESSIONS.md).
#include "fuzz_input.h"
#include "tissue/scene/session.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto file = tissue::fuzz::inputFile(data, size, ".json");
  auto session = tissue::scene::loadSession(file);
  if (!session) tissue::fuzz::checkRefusal(session.error().message, file);
  return 0;
}
