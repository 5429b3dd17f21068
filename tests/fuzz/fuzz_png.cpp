// Fuzz target: PNG textures (tissue::readImage, stb_image inside), as RGBA and as stored.
#include "fuzz_input.h"
#include "tissue/core/image.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto file = tissue::fuzz::inputFile(data, size, ".png");
  for (int channels : {0, 4}) {
    auto image = tissue::readImage(file, channels);
    if (!image) tissue::fuzz::checkRefusal(image.error().message, file);
  }
  return 0;
}
