// The stb adapter: stb_image and stb_image_write are used here and nowhere else.
#include <algorithm>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <span>
#include <string>

#include "tissue/core/atomic_file.h"
#include "tissue/core/image.h"

#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STBI_FAILURE_USERMSG
// PNG only: every texture tissue ships and reads is PNG, and Debian's stb_image JPEG decoder
// indexes past its Huffman table on a damaged file (UBSan, found by the image fuzz target), its
// TGA decoder loops for minutes on a damaged header. Fewer decoders, less to go wrong inside a
// trainee's session.
#define STBI_ONLY_PNG
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

namespace {

std::uint32_t bigEndian32(const std::uint8_t* p) {
  return std::uint32_t(p[0]) << 24 | std::uint32_t(p[1]) << 16 | std::uint32_t(p[2]) << 8 | p[3];
}

/// A PNG's chunk lengths against the file's size, before stb sees it: stb_image (Debian's 2.x)
/// adds a chunk's declared length to its read pointer before comparing, which is undefined
/// behaviour for a length past the end (found by the PNG fuzz target under UBSan).
Result<void> checkPngChunks(const std::filesystem::path& path, std::span<const std::uint8_t> bytes) {
  static constexpr std::uint8_t kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (bytes.size() < 8 || !std::equal(kSignature, kSignature + 8, bytes.begin())) return {};  // not a PNG
  std::size_t at = 8;
  for (int chunk = 1; at + 12 <= bytes.size(); ++chunk) {
    const std::uint32_t length = bigEndian32(bytes.data() + at);
    if (length > bytes.size() - at - 12)
      return Error{"cannot read image '" + path.string() + "': PNG chunk " + std::to_string(chunk) +
                   " declares " + std::to_string(length) +
                   " bytes, more than the file holds; the file is truncated or damaged"};
    if (std::equal(bytes.begin() + std::ptrdiff_t(at + 4), bytes.begin() + std::ptrdiff_t(at + 8), "IEND"))
      return {};
    at += 12 + length;
  }
  return Error{"cannot read image '" + path.string() +
               "': the PNG ends before its IEND chunk; the file is truncated"};
}

}  // namespace

Result<Image8> readImage(const std::filesystem::path& path, int forceChannels) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return Error{"cannot read image '" + path.string() + "': cannot open it; check the path"};
  const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)),
                                        std::istreambuf_iterator<char>());
  if (auto ok = checkPngChunks(path, bytes); !ok) return ok.error();
  if (bytes.size() > std::size_t(std::numeric_limits<int>::max()))
    return Error{"cannot read image '" + path.string() + "': larger than 2 GiB"};
  int w = 0, h = 0, c = 0;
  // The declared size against the file's before decoding (a damaged header declared 65535 x
  // 65535 to stb: the image fuzz target): deflate packs at most 1032 bytes into one, so no PNG
  // holds more than about a thousand pixels per byte, and the renderer's textures stop at 16384
  // on a side.
  if (stbi_info_from_memory(bytes.data(), int(bytes.size()), &w, &h, &c)) {
    constexpr double kPixelsPerByte = 1100.0, kMaxSide = 16384.0;
    if (double(w) > kMaxSide || double(h) > kMaxSide ||
        double(w) * double(h) > kPixelsPerByte * double(bytes.size()))
      return Error{"cannot read image '" + path.string() + "': its header declares " + std::to_string(w) +
                   " x " + std::to_string(h) + " pixels, more than a " + std::to_string(bytes.size()) +
                   "-byte file can hold (or over 16384 on a side); the file is damaged or truncated"};
  }
  stbi_uc* data = stbi_load_from_memory(bytes.data(), int(bytes.size()), &w, &h, &c, forceChannels);
  if (!data) {
    return Error{"cannot read image '" + path.string() + "': " + stbi_failure_reason() + "; give a PNG file"};
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
