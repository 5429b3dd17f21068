// The stb adapter: stb_image and stb_image_write are used here and nowhere else.
#include <algorithm>
#include <cstring>

#include "tissue/core/atomic_file.h"
#include "tissue/core/image.h"

#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STBI_FAILURE_USERMSG
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wold-style-cast"
#pragma GCC diagnostic ignored "-Wcast-align"
#pragma GCC diagnostic ignored "-Wdouble-promotion"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wnull-dereference"
#pragma GCC diagnostic ignored "-Wshadow"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wimplicit-fallthrough"
#include <stb/stb_image.h>
#include <stb/stb_image_write.h>
#pragma GCC diagnostic pop

namespace tissue {
namespace {

void appendBytes(void* context, void* data, int size) {
  auto* out = static_cast<std::vector<std::uint8_t>*>(context);
  const auto* bytes = static_cast<const std::uint8_t*>(data);
  out->insert(out->end(), bytes, bytes + size);
}

}  // namespace

Result<void> writePng(const std::filesystem::path& path, const Image8& image) {
  if (image.width <= 0 || image.height <= 0 || image.channels < 1 || image.channels > 4 ||
      image.pixels.size() != std::size_t(image.width) * image.height * image.channels) {
    return Error{"cannot write '" + path.string() + "': the image is empty or its size is inconsistent"};
  }
  std::vector<std::uint8_t> png;
  png.reserve(image.pixels.size() / 2);
  const int ok = stbi_write_png_to_func(appendBytes, &png, image.width, image.height, image.channels,
                                        image.pixels.data(), image.width * image.channels);
  if (!ok) return Error{"cannot encode PNG for '" + path.string() + "'"};
  return writeFileAtomic(path, png);
}

Result<Image8> readImage(const std::filesystem::path& path, int forceChannels) {
  int w = 0, h = 0, c = 0;
  stbi_uc* data = stbi_load(path.c_str(), &w, &h, &c, forceChannels);
  if (!data) {
    return Error{"cannot read image '" + path.string() + "': " + stbi_failure_reason() +
                 "; give a PNG, JPEG or TGA file"};
  }
  const int channels = forceChannels ? forceChannels : c;
  Image8 image(w, h, channels);
  std::memcpy(image.pixels.data(), data, image.pixels.size());
  stbi_image_free(data);
  return image;
}

void flipVertically(Image8& image) {
  const std::size_t row = std::size_t(image.width) * image.channels;
  for (int y = 0; y < image.height / 2; ++y) {
    std::swap_ranges(image.pixels.begin() + std::ptrdiff_t(y * row),
                     image.pixels.begin() + std::ptrdiff_t((y + 1) * row),
                     image.pixels.begin() + std::ptrdiff_t((image.height - 1 - y) * row));
  }
}

}  // namespace tissue
